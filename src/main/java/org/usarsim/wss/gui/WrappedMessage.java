package org.usarsim.wss.gui;

import java.awt.Dimension;
import java.awt.FontMetrics;
import javax.swing.JTextArea;
import javax.swing.UIManager;

/**
 * A message dialog's text wrapped at words to a readable width (at most {@link #WIDTH} pixels),
 * for a {@code JOptionPane}: a long reason (a path, a model's why) otherwise makes the dialog one
 * line as wide as the screen. Selectable, so that it can be copied; not editable. Event thread.
 */
final class WrappedMessage {

    /** The widest a message's lines get, in pixels. */
    static final int WIDTH = 520;

    private WrappedMessage() {
    }

    /** The text in an area as wide as its longest line up to {@link #WIDTH}, as tall as its wrapped lines. */
    static JTextArea of(String text) {
        JTextArea area = new JTextArea(text);
        area.setName("messageText");
        area.setEditable(false);
        area.setLineWrap(true);
        area.setWrapStyleWord(true);
        area.setOpaque(false);
        area.setBorder(null);
        if (UIManager.getFont("OptionPane.messageFont") != null) {
            area.setFont(UIManager.getFont("OptionPane.messageFont"));
        } else if (UIManager.getFont("Label.font") != null) {
            area.setFont(UIManager.getFont("Label.font"));
        }
        FontMetrics metrics = area.getFontMetrics(area.getFont());
        int longest = 0;
        for (String line : text.split("\n", -1)) {
            longest = Math.max(longest, metrics.stringWidth(line));
        }
        int width = Math.min(WIDTH, longest + 4);
        // The height the text takes once wrapped at that width.
        area.setSize(new Dimension(width, Short.MAX_VALUE));
        area.setPreferredSize(new Dimension(width, area.getPreferredSize().height));
        return area;
    }
}
