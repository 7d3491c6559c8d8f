package org.usarsim.wss.gui;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.GridLayout;
import java.awt.Insets;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.util.List;
import java.util.prefs.BackingStoreException;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.KeyStroke;
import javax.swing.SwingConstants;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import javax.swing.text.JTextComponent;

/**
 * What the settings dialogs share ({@link DistanceModelDialog}, {@link GeneratedModelDialog},
 * {@link LinkShapingDialog}, {@link RateLimitDialog}): the component names tests find, the colours
 * of a refusal, the buttons, a row of label, field and unit, the words of a refusal, storing the
 * values; their checked fields are {@link CheckedField}s, what OK refused {@link Refusals}.
 */
final class DialogParts {

    /** Component names, for tests and accessibility tools; each value field is named by its key. */
    static final String MESSAGE = "message";
    static final String OK = "ok";
    static final String CANCEL = "cancel";
    static final String CLOSE = "close";

    /** The background of a field whose value is refused. */
    static final Color INVALID = new Color(255, 205, 205);

    static final Color MESSAGE_COLOR = new Color(170, 0, 0);
    /** Read-only values stay readable: darker than the look and feel's pale disabled text. */
    static final Color READ_ONLY_TEXT = new Color(90, 90, 90);

    private DialogParts() {
    }

    /**
     * Lays the dialog out: the groups one under the other, the message (two lines high, for a
     * refusal, as wide as the dialog), the buttons at the bottom right; packs it, never smaller
     * than that, centred on its owner.
     */
    static void layOut(JDialog dialog, Window owner, List<? extends JComponent> groups, JLabel message, JPanel buttons) {
        JPanel content = new JPanel(new GridBagLayout());
        content.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = 0;
        c.fill = GridBagConstraints.HORIZONTAL;
        c.weightx = 1;
        c.insets = new Insets(0, 0, 6, 0);
        groups.forEach(group -> content.add(group, c));
        message.setName(MESSAGE);
        message.setForeground(MESSAGE_COLOR);
        message.setVerticalAlignment(SwingConstants.TOP);
        content.add(message, c);
        c.weighty = 1;
        c.anchor = GridBagConstraints.SOUTHEAST;
        c.fill = GridBagConstraints.NONE;
        c.insets = new Insets(0, 0, 0, 0);
        content.add(buttons, c);
        dialog.setContentPane(content);
        dialog.pack();
        // Two lines for a refusal, as wide as the dialog; the HTML text wraps within it.
        int lineHeight = message.getFontMetrics(message.getFont()).getHeight();
        message.setPreferredSize(new Dimension(10, 2 * lineHeight + 2));
        dialog.pack();
        dialog.setMinimumSize(dialog.getSize());
        dialog.setLocationRelativeTo(owner);
    }

    /** A grid cell of a row of label, field and unit: the last one takes the row's spare width. */
    static GridBagConstraints cell(int x, int y, int leftInset, boolean last) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = x;
        c.gridy = y;
        c.anchor = GridBagConstraints.LINE_START;
        c.insets = new Insets(3, leftInset, 3, 0);
        c.weightx = last ? 1 : 0;
        return c;
    }

    /** A row of a group: the label, the field after it, then what goes beside (a unit, a button), which takes the spare width. */
    static void row(JPanel panel, int y, JLabel label, JComponent field, JComponent beside) {
        panel.add(label, cell(0, y, 0, false));
        panel.add(field, cell(1, y, 8, false));
        panel.add(beside, cell(2, y, 6, true));
    }

    /** The unit after a field, its help as tooltip. */
    static JLabel unit(String text, String help) {
        JLabel unit = new JLabel(text);
        unit.setToolTipText(help);
        return unit;
    }

    /** A check box named for tests, its help as tooltip, ticked or not, greyed unless {@code editable}. */
    static JCheckBox checkBox(JCheckBox box, String name, String help, boolean selected, boolean editable) {
        box.setName(name);
        box.setToolTipText(help);
        box.setSelected(selected);
        box.setEnabled(editable);
        return box;
    }

    /** Storing a dialog's values, which may fail. */
    @FunctionalInterface
    interface Store {
        void store() throws BackingStoreException;
    }

    /** Stores the values; when that fails, says so in {@code message} and returns false (the dialog stays open). */
    static boolean stored(JLabel message, Store store) {
        try {
            store.store();
            return true;
        } catch (BackingStoreException | RuntimeException e) {
            showMessage(message, "Cannot save the settings: " + e.getMessage());
            return false;
        }
    }

    /** A panel with a titled border, for a group of fields. */
    static JPanel titled(String title) {
        JPanel panel = new JPanel(new GridBagLayout());
        panel.setBorder(BorderFactory.createCompoundBorder(BorderFactory.createTitledBorder(title),
                BorderFactory.createEmptyBorder(0, 6, 4, 6)));
        return panel;
    }

    /**
     * OK and Cancel, or Close alone when not {@code editable}; Enter presses the first, Escape and
     * Cancel/Close dispose of the dialog.
     */
    static JPanel buttons(JDialog dialog, boolean editable, Runnable ok) {
        JPanel panel = new JPanel(new GridLayout(1, 0, 6, 0));
        JButton cancel;
        JButton first;
        if (editable) {
            first = button("OK", OK);
            first.addActionListener(e -> ok.run());
            cancel = button("Cancel", CANCEL);
            panel.add(first);
            panel.add(cancel);
        } else {
            cancel = button("Close", CLOSE);
            first = cancel;
            panel.add(cancel);
        }
        cancel.addActionListener(e -> dialog.dispose());
        dialog.getRootPane().setDefaultButton(first);
        dialog.getRootPane().registerKeyboardAction(e -> dialog.dispose(), KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0),
                JComponent.WHEN_IN_FOCUSED_WINDOW);
        return panel;
    }

    private static JButton button(String text, String name) {
        JButton button = new JButton(text);
        button.setName(name);
        return button;
    }

    static JLabel label(String text, String tip, JComponent field) {
        JLabel label = new JLabel(text);
        label.setToolTipText(tip);
        label.setLabelFor(field);
        return label;
    }

    /** Disabled, its text still readable, on the grey of a field that cannot be edited (not an editable field's white). */
    static void readOnly(JTextComponent field) {
        field.setEnabled(false);
        field.setDisabledTextColor(READ_ONLY_TEXT);
        field.setBackground(readOnlyBackground());
    }

    /** The look and feel's pale text of a disabled field: a read-only value that is not used. */
    static Color unusedText() {
        Color pale = javax.swing.UIManager.getColor("TextField.inactiveForeground");
        return pale != null ? pale : Color.GRAY;
    }

    /** Gives a group made by {@link #titled} a new title. */
    static void retitle(JPanel group, String title) {
        javax.swing.border.TitledBorder border = (javax.swing.border.TitledBorder)
                ((javax.swing.border.CompoundBorder) group.getBorder()).getOutsideBorder();
        if (!title.equals(border.getTitle())) {
            border.setTitle(title);
            group.revalidate();
            group.repaint();
        }
    }

    /** The look and feel's grey of a field that cannot be edited. */
    static Color readOnlyBackground() {
        Color grey = javax.swing.UIManager.getColor("TextField.inactiveBackground");
        return grey != null ? grey : javax.swing.UIManager.getColor("control");
    }

    /** The words of a refused value: "Timeout (ms): '50' is not a whole number of ...". */
    static String refusal(String label, String text, String problem) {
        return label + ": '" + text.strip() + "' is not " + problem;
    }

    /** Shows a refusal in the message label, wrapped to its width. */
    static void showMessage(JLabel message, String text) {
        message.setText("<html>" + text.replace("&", "&amp;").replace("<", "&lt;") + "</html>");
    }

    static DocumentListener onChange(Runnable action) {
        return new DocumentListener() {
            @Override
            public void insertUpdate(DocumentEvent e) {
                action.run();
            }

            @Override
            public void removeUpdate(DocumentEvent e) {
                action.run();
            }

            @Override
            public void changedUpdate(DocumentEvent e) {
            }
        };
    }
}
