package org.usarsim.wss.gui;

import java.awt.BorderLayout;
import java.util.List;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.text.BadLocationException;
import javax.swing.text.Document;
import javax.swing.text.Element;

/** The log at the bottom of the window: the server's lines, the newest last, at most {@link #MAX_LINES}. */
final class LogPanel extends JPanel {

    static final int MAX_LINES = 2000;

    private final JTextArea text = new JTextArea(8, 80);

    LogPanel() {
        super(new BorderLayout());
        text.setName("log");
        text.setEditable(false);
        text.setLineWrap(false);
        add(new JScrollPane(text), BorderLayout.CENTER);
    }

    /** Appends the lines in one edit and drops the oldest beyond the limit. Event thread. */
    void append(List<String> lines) {
        if (lines.isEmpty()) {
            return;
        }
        int from = Math.max(0, lines.size() - MAX_LINES);
        StringBuilder batch = new StringBuilder();
        for (String line : lines.subList(from, lines.size())) {
            batch.append(line).append('\n');
        }
        Document document = text.getDocument();
        try {
            document.insertString(document.getLength(), batch.toString(), null);
            Element root = document.getDefaultRootElement();
            // The last element is the empty line after the final newline.
            int excess = root.getElementCount() - 1 - MAX_LINES;
            if (excess > 0) {
                document.remove(0, root.getElement(excess - 1).getEndOffset());
            }
        } catch (BadLocationException e) {
            throw new IllegalStateException(e);
        }
        text.setCaretPosition(document.getLength());
    }
}
