package org.usarsim.wss.gui;

import java.awt.Window;
import java.util.List;
import java.util.function.Function;
import java.util.function.UnaryOperator;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.shaping.Bitrate;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * "Limit rate..." of the {@link ForceMenu}: asks the rate (bit/s, {@code k} and {@code M}
 * allowed: {@code 1M}) and, optionally, the delay and its jitter (ms) to pin on a pair, both ways, read as
 * {@code FORCE ... {Rate 1M} {Delay 50} {Jitter 20}} reads them ({@link Bitrate#parse},
 * {@link ShapingConfig#parseDelayMs}, {@link ShapingConfig#parseJitterMs}). A field whose value is refused turns red as it is typed;
 * OK refuses with the first reason under the fields, else closes with the pin. Modal; build and
 * show it on the event thread. It does not call the hub: the menu does, with {@link #pin()}.
 */
final class RateLimitDialog extends JDialog {

    /** Component names, for tests; the message and the buttons are named as in {@link DialogParts}. */
    static final String RATE = "rate";
    static final String DELAY = "delay";
    static final String RATE_LABEL = "Rate";
    static final String DELAY_LABEL = "Delay";
    static final String JITTER = "jitter";
    static final String JITTER_LABEL = "Jitter";
    private static final int MIN_WIDTH = 480;

    private final JLabel message = new JLabel(" ");
    private final CheckedField rate;
    private final CheckedField delay;
    private final CheckedField jitter;
    private RatePin pin;

    RateLimitDialog(Window owner, String robotA, String robotB) {
        super(owner, "Limit rate " + robotA + " - " + robotB, ModalityType.APPLICATION_MODAL);
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        JPanel fields = DialogParts.titled("Force " + robotA + " - " + robotB + " up, both ways, until released");
        rate = row(fields, 0, RATE_LABEL, RATE, "bit/s",
                "The link's rate each way: a number of bit/s, with k for 1000 or M for 1000000 (800, 512k, 1.5M, 54M)",
                text -> refusal(RATE_LABEL, text, Bitrate::parse));
        delay = row(fields, 1, DELAY_LABEL, DELAY, "ms (empty: the setting's)",
                "The delay of every byte besides its airtime, whole milliseconds from " + ShapingConfig.MIN_DELAY_MS + " to "
                        + ShapingConfig.MAX_DELAY_MS + "; empty keeps wss.shaping.delayMs",
                text -> text.isBlank() ? null : refusal(DELAY_LABEL, text, ShapingConfig::parseDelayMs));
        jitter = row(fields, 2, JITTER_LABEL, JITTER, "ms (empty: the setting's)",
                "How much the delay varies, with the run's distribution (docs/shaping.md, \"Jitter\"), whole milliseconds from 0 to "
                        + ShapingConfig.MAX_JITTER_MS + "; empty keeps wss.shaping.jitter",
                text -> text.isBlank() ? null : refusal(JITTER_LABEL, text, ShapingConfig::parseJitterMs));
        DialogParts.layOut(this, owner, List.of(fields), message, DialogParts.buttons(this, true, this::ok));
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

    /** The rate, delay and jitter OK accepted; null before (or when the dialog was cancelled). */
    RatePin pin() {
        return pin;
    }

    /** A row of the dialog: the label, the field checked by {@code rule} (its words: "Rate: ..."), the unit. */
    private CheckedField row(JPanel panel, int y, String label, String name, String unit, String help, UnaryOperator<String> rule) {
        CheckedField field = new CheckedField(new JTextField(10), name, help, rule, message, () -> { });
        DialogParts.row(panel, y, DialogParts.label(label, help, field.field()), field.field(), DialogParts.unit(unit, help));
        return field;
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

    private void ok() {
        Refusals refused = new Refusals();
        for (CheckedField field : List.of(rate, delay, jitter)) {
            String problem = field.mark();
            if (problem != null) {
                refused.add(field.field(), problem);
            }
        }
        if (refused.show(message)) {
            return;
        }
        String delayText = delay.field().getText();
        String jitterText = jitter.field().getText();
        pin = new RatePin(Bitrate.parse(rate.field().getText()), delayText.isBlank() ? -1 : ShapingConfig.parseDelayMs(delayText),
                jitterText.isBlank() ? -1 : ShapingConfig.parseJitterMs(jitterText));
        dispose();
    }
}
