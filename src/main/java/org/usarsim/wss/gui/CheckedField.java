package org.usarsim.wss.gui;

import java.awt.Color;
import java.util.function.UnaryOperator;
import javax.swing.JLabel;
import javax.swing.JTextField;

/**
 * A dialog's text field whose value a rule checks as it is typed, as every settings dialog has
 * them: named (for tests), its help as tooltip, never squeezed below its width, red while the rule
 * refuses its text (else white, or grey while disabled), and each change clears the dialog's
 * message, since a refusal there speaks of the values OK saw. Event thread.
 */
final class CheckedField {

    private final JTextField field;
    private final UnaryOperator<String> rule;
    private final String help;
    private final Color normalBackground;
    private boolean problemInTip;

    /**
     * Makes {@code field} such a field: {@code rule} gives the words of a refusal of a text, or
     * null when it accepts it; after each change the field is marked, {@code message} cleared and
     * {@code changed} run.
     */
    CheckedField(JTextField field, String name, String help, UnaryOperator<String> rule, JLabel message, Runnable changed) {
        this.field = field;
        this.rule = rule;
        this.help = help;
        this.normalBackground = field.getBackground();
        field.setName(name);
        field.setToolTipText(help);
        field.setMinimumSize(field.getPreferredSize());
        field.getDocument().addDocumentListener(DialogParts.onChange(() -> {
            mark();
            message.setText(" ");
            changed.run();
        }));
    }

    /** While refused, the tooltip says why instead of the help. */
    CheckedField problemInTip() {
        problemInTip = true;
        mark();
        return this;
    }

    JTextField field() {
        return field;
    }

    /** The text, stripped of surrounding whitespace. */
    String text() {
        return field.getText().strip();
    }

    /** Why the rule refuses the text, or null. */
    String problem() {
        return rule.apply(field.getText());
    }

    /** Marks the field by what the rule says of its text now; the words of the refusal, or null. */
    String mark() {
        String problem = problem();
        field.setBackground(problem != null ? DialogParts.INVALID
                : field.isEnabled() ? normalBackground : DialogParts.readOnlyBackground());
        if (problemInTip) {
            field.setToolTipText(problem != null ? problem : help);
        }
        return problem;
    }
}
