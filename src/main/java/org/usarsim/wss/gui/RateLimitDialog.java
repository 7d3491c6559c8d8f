package org.usarsim.wss.gui;

import java.awt.Color;
import java.awt.Window;
import java.util.function.Function;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.shaping.Bitrate;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * "Limit rate..." of the {@link ForceMenu}: asks the rate (bit/s, {@code k} and {@code M}
 * allowed: {@code 1M}) and, optionally, the delay (ms) to pin on a pair, both ways, read as
 * {@code FORCE ... {Rate 1M} {Delay 50}} reads them ({@link Bitrate#parse},
 * {@link ShapingConfig#parseDelayMs}). A field whose value is refused turns red as it is typed;
 * OK refuses with the first reason under the fields, else closes with the pin. Modal; build and
 * show it on the event thread. It does not call the hub: the menu does, with {@link #pin()}.
 */
final class RateLimitDialog extends JDialog {

    /** Component names, for tests; the message and the buttons are named as in {@link DialogParts}. */
    static final String RATE = "rate";
    static final String DELAY = "delay";
    static final String RATE_LABEL = "Rate";
    static final String DELAY_LABEL = "Delay";
    private static final int MIN_WIDTH = 480;

    private final JTextField rate = new JTextField(10);
    private final JTextField delay = new JTextField(10);
    private final JLabel message = new JLabel(" ");
    private final Color normalBackground = rate.getBackground();
    private RatePin pin;

    RateLimitDialog(Window owner, String robotA, String robotB) {
        super(owner, "Limit rate " + robotA + " - " + robotB, ModalityType.APPLICATION_MODAL);
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        JPanel fields = DialogParts.titled("Force " + robotA + " - " + robotB + " up, both ways, until released");
        row(fields, 0, RATE_LABEL, rate, RATE, "bit/s",
                "The link's rate each way: a number of bit/s, with k for 1000 or M for 1000000 (800, 512k, 1.5M, 54M)");
        row(fields, 1, DELAY_LABEL, delay, DELAY, "ms (empty: the setting's)",
                "The delay of every byte besides its airtime, whole milliseconds from " + ShapingConfig.MIN_DELAY_MS + " to "
                        + ShapingConfig.MAX_DELAY_MS + "; empty keeps wss.shaping.delayMs");
        DialogParts.layOut(this, owner, java.util.List.of(fields), message, DialogParts.buttons(this, true, this::ok));
        // Wide enough for the longest refusal (a rate's, with its examples) in the message's two lines.
        setMinimumSize(new java.awt.Dimension(Math.max(getWidth(), MIN_WIDTH), getHeight()));
        setSize(getMinimumSize());
        setLocationRelativeTo(owner);
    }

    /** Shows the dialog for the pair and waits for it to close: the pin OK accepted, or null (Cancel, Escape, closed). Event thread. */
    static RatePin ask(Window owner, String robotA, String robotB) {
        RateLimitDialog dialog = new RateLimitDialog(owner, robotA, robotB);
        dialog.setVisible(true);
        return dialog.pin();
    }

    /** The rate and delay OK accepted; null before (or when the dialog was cancelled). */
    RatePin pin() {
        return pin;
    }

    private void row(JPanel panel, int y, String label, JTextField field, String name, String unit, String help) {
        field.setName(name);
        field.setToolTipText(help);
        field.setMinimumSize(field.getPreferredSize());
        field.getDocument().addDocumentListener(DialogParts.onChange(() -> {
            mark(field, problem(field) != null);
            message.setText(" "); // a refusal speaks of the values OK saw; the marks stay current
        }));
        panel.add(DialogParts.label(label, help, field), DialogParts.cell(0, y, 0, false));
        panel.add(field, DialogParts.cell(1, y, 8, false));
        JLabel units = new JLabel(unit);
        units.setToolTipText(help);
        panel.add(units, DialogParts.cell(2, y, 6, true));
    }

    /** Why the field's value is refused ("Rate: ..."), or null when it is accepted. */
    private String problem(JTextField field) {
        if (field == rate) {
            return refusal(RATE_LABEL, rate.getText(), Bitrate::parse);
        }
        return delay.getText().isBlank() ? null : refusal(DELAY_LABEL, delay.getText(), ShapingConfig::parseDelayMs);
    }

    /** The parser's own words for a refused value, after the field's label; null when it reads it. */
    private static String refusal(String label, String text, Function<String, ?> parse) {
        try {
            parse.apply(text);
            return null;
        } catch (IllegalArgumentException e) {
            return label + ": " + e.getMessage();
        }
    }

    private void mark(JTextField field, boolean invalid) {
        field.setBackground(invalid ? DialogParts.INVALID : normalBackground);
    }

    private void ok() {
        String rateProblem = problem(rate);
        String delayProblem = problem(delay);
        mark(rate, rateProblem != null);
        mark(delay, delayProblem != null);
        if (rateProblem != null || delayProblem != null) {
            boolean both = rateProblem != null && delayProblem != null;
            DialogParts.showMessage(message, (rateProblem != null ? rateProblem : delayProblem) + (both ? " (and 1 more marked)" : ""));
            (rateProblem != null ? rate : delay).requestFocusInWindow();
            return;
        }
        pin = new RatePin(Bitrate.parse(rate.getText()), delay.getText().isBlank() ? -1 : ShapingConfig.parseDelayMs(delay.getText()));
        dispose();
    }
}
