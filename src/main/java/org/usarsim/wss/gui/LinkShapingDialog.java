package org.usarsim.wss.gui;

import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Window;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.swing.BorderFactory;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import org.usarsim.wss.shaping.JitterDistribution;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * "Link shaping...": the {@code wss.shaping*} settings of the window (docs/shaping.md) for
 * its next Start, laid out as the generated model dialog: shape links (a check box), the rate
 * table, the delay, shared airtime (a check box), the queue, the jitter, its distribution (a list)
 * and whether datagrams may be reordered (a check box), each field named by its key. A rate
 * table, a delay or a queue that is refused turns its field red as it is typed, the reason in its
 * tooltip; OK checks them with the same rules ({@link ShapingValues#problem}) and refuses with the
 * first reason under the fields, else stores the values in the {@link WindowPreferences}.
 * Read-only while a server runs (every field disabled, Close only). Modal; build and show it on
 * the event thread.
 */
final class LinkShapingDialog extends JDialog {

    static final String TITLE = "Link shaping";
    static final String RATES_LABEL = "Rates by strength";
    static final String DELAY_LABEL = "Delay";
    static final String QUEUE_LABEL = "Queue";
    static final String JITTER_LABEL = "Jitter";
    private static final String JITTER_HELP = "How much each grant's or datagram's delay varies, drawn from the distribution below:"
            + " whole milliseconds from 0 to " + ShapingConfig.MAX_JITTER_MS + ", 0 none; a TCP link's bytes keep their order"
            + " (wss.shaping.jitter, docs/shaping.md \"Jitter\")";
    private static final String RATES_HELP = "Steps dBm:rate from the strongest signal to the weakest, comma-separated:"
            + " a pair whose strength is at or above a step's dBm gets its rate; below the last, the last."
            + " A rate is bit/s with k for 1000 or M for 1000000 (wss.shaping.rates)";
    private static final String DELAY_HELP = "Bytes reach the target no sooner than this after the WSS read them, plus their time on"
            + " the air: whole milliseconds from " + ShapingConfig.MIN_DELAY_MS + " to " + ShapingConfig.MAX_DELAY_MS
            + " (wss.shaping.delayMs)";
    private static final String QUEUE_HELP = "The most a link holds one way beyond its delay, as a radio's queue holds frames:"
            + " in time at the link's rate, whole milliseconds from " + ShapingConfig.MIN_QUEUE_MS + " to " + ShapingConfig.MAX_QUEUE_MS
            + "; then the sender waits, as TCP makes it (wss.shaping.queueMs)";

    /** Each text field's label, by its key, for a refusal under the fields. */
    private static final Map<String, String> LABELS = Map.of(ShapingConfig.RATES, RATES_LABEL, ShapingConfig.DELAY_MS, DELAY_LABEL,
            ShapingConfig.QUEUE_MS, QUEUE_LABEL, ShapingConfig.JITTER, JITTER_LABEL);

    private final boolean editable;
    private final WindowPreferences preferences;
    private final JCheckBox shaping = new JCheckBox("Shape every link like radio");
    private final JCheckBox airtime = new JCheckBox("A robot's links share its radio's airtime");
    private final JCheckBox reorder = new JCheckBox("A fixed UDP port's datagrams may overtake each other by their jitter");
    private final JComboBox<String> distribution = new JComboBox<>(
            java.util.Arrays.stream(JitterDistribution.values()).map(JitterDistribution::word).toArray(String[]::new));
    private final JLabel message = new JLabel(" ");
    private final CheckedField rates;
    private final CheckedField delay;
    private final CheckedField queue;
    private final CheckedField jitter;
    private boolean saved;

    /** Shows {@code values} (a value for each of {@link ShapingValues#KEYS}); OK stores them in {@code preferences}. */
    LinkShapingDialog(Window owner, boolean editable, WindowPreferences preferences, Map<String, String> values) {
        super(owner, TITLE, ModalityType.APPLICATION_MODAL);
        this.editable = editable;
        this.preferences = preferences;
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);

        JPanel rows = DialogParts.titled(editable ? "For the next Start" : "Of the server that runs (Stop it to change them)");
        box(rows, 0, "Link shaping", shaping, ShapingConfig.SHAPING, "on".equalsIgnoreCase(values.get(ShapingConfig.SHAPING)),
                "Shape every link: rate and delay from the signal strength, a robot's airtime shared (wss.shaping, docs/shaping.md)");
        rates = field(rows, 1, RATES_LABEL, new JTextField(40), ShapingConfig.RATES, values.get(ShapingConfig.RATES), "dBm:rate, strongest first",
                RATES_HELP);
        delay = field(rows, 2, DELAY_LABEL, new JTextField(6), ShapingConfig.DELAY_MS, values.get(ShapingConfig.DELAY_MS), "ms, besides each byte's airtime",
                DELAY_HELP);
        box(rows, 3, "Shared airtime", airtime, ShapingConfig.AIRTIME, Boolean.parseBoolean(values.get(ShapingConfig.AIRTIME)),
                "Links sharing a robot share its radio's airtime, by time (wss.shaping.airtime)");
        queue = field(rows, 4, QUEUE_LABEL, new JTextField(6), ShapingConfig.QUEUE_MS, values.get(ShapingConfig.QUEUE_MS), "ms at the link's rate, beyond its delay",
                QUEUE_HELP);
        jitter = field(rows, 5, JITTER_LABEL, new JTextField(6), ShapingConfig.JITTER, values.get(ShapingConfig.JITTER), "ms, 0: none",
                JITTER_HELP);
        String distributionHelp = "The jitter's distribution, as netem names them: uniform (delay +- jitter), normal, pareto,"
                + " paretonormal (wss.shaping.jitterDistribution)";
        distribution.setName(ShapingConfig.JITTER_DISTRIBUTION);
        distribution.setToolTipText(distributionHelp);
        JitterDistribution chosen = JitterDistribution.of(values.get(ShapingConfig.JITTER_DISTRIBUTION));
        distribution.setSelectedItem((chosen == null ? JitterDistribution.UNIFORM : chosen).word());
        distribution.setEnabled(editable);
        rows.add(DialogParts.label("Jitter distribution", distributionHelp, distribution), DialogParts.cell(0, 6, 0, false));
        rows.add(distribution, DialogParts.cell(1, 6, 8, true));
        box(rows, 7, "Reorder datagrams", reorder, ShapingConfig.REORDER, Boolean.parseBoolean(values.get(ShapingConfig.REORDER)),
                "With a jitter, each datagram of a fixed UDP port goes at its own time, so a later one may overtake;"
                        + " off, each waits for the one before (wss.shaping.reorder)");

        DialogParts.layOut(this, owner, List.of(rows), message, DialogParts.buttons(this, editable, this::ok));
        // Three lines for a refusal: a rate table's repeats the table.
        int lineHeight = message.getFontMetrics(message.getFont()).getHeight();
        message.setPreferredSize(new Dimension(10, 3 * lineHeight + 2));
        pack();
        setMinimumSize(getSize());
        setLocationRelativeTo(owner);
    }

    /** Shows the dialog and waits for it to close: whether OK stored the values. Event thread. */
    static boolean show(Window owner, boolean editable, WindowPreferences preferences, Map<String, String> values) {
        LinkShapingDialog dialog = new LinkShapingDialog(owner, editable, preferences, values);
        dialog.setVisible(true);
        return dialog.saved();
    }

    /** Whether OK stored the values. */
    boolean saved() {
        return saved;
    }

    private void box(JPanel panel, int y, String label, JCheckBox box, String key, boolean selected, String help) {
        DialogParts.checkBox(box, key, help, selected, editable);
        panel.add(DialogParts.label(label, help, box), DialogParts.cell(0, y, 0, false));
        panel.add(box, DialogParts.cell(1, y, 4, true));
    }

    /** A text field checked by {@link ShapingValues#problem}, the reason in its tooltip while refused, its unit right after it. */
    private CheckedField field(JPanel panel, int y, String label, JTextField text, String key, String value, String unit, String help) {
        CheckedField field = new CheckedField(text, key, help, typed -> ShapingValues.problem(key, typed), message, () -> { });
        text.setText(value);
        field.problemInTip();
        if (!editable) {
            DialogParts.readOnly(text);
        }
        JLabel units = DialogParts.unit(unit, help);
        units.setBorder(BorderFactory.createEmptyBorder(0, 6, 0, 0));
        JPanel beside = new JPanel(new FlowLayout(FlowLayout.LEADING, 0, 0)); // the unit right after a short field too
        beside.add(text);
        beside.add(units);
        panel.add(DialogParts.label(label, help, text), DialogParts.cell(0, y, 0, false));
        panel.add(beside, DialogParts.cell(1, y, 8, true));
        return field;
    }

    private void ok() {
        Map<String, String> values = new LinkedHashMap<>();
        values.put(ShapingConfig.SHAPING, shaping.isSelected() ? "on" : "off");
        values.put(ShapingConfig.RATES, rates.text());
        values.put(ShapingConfig.DELAY_MS, delay.text());
        values.put(ShapingConfig.AIRTIME, String.valueOf(airtime.isSelected()));
        values.put(ShapingConfig.QUEUE_MS, queue.text());
        values.put(ShapingConfig.JITTER, jitter.text());
        values.put(ShapingConfig.JITTER_DISTRIBUTION, String.valueOf(distribution.getSelectedItem()));
        values.put(ShapingConfig.REORDER, String.valueOf(reorder.isSelected()));
        Refusals refused = new Refusals();
        for (CheckedField field : List.of(rates, delay, queue, jitter)) {
            String problem = field.problem();
            if (problem != null) {
                refused.add(field.field(), LABELS.get(field.field().getName()) + ": " + problem);
            }
        }
        if (refused.show(message) || !DialogParts.stored(message, () -> preferences.storeShaping(values))) {
            return;
        }
        saved = true;
        dispose();
    }
}
