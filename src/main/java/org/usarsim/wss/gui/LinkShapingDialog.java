package org.usarsim.wss.gui;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Window;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.prefs.BackingStoreException;
import javax.swing.BorderFactory;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * "Link shaping...": the five {@code wss.shaping*} settings of the window (docs/shaping.md) for
 * its next Start, laid out as the generated model dialog: shape links (a check box), the rate
 * table, the delay, shared airtime (a check box), the queue, each field named by its key. A rate
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
            ShapingConfig.QUEUE_MS, QUEUE_LABEL);

    private final boolean editable;
    private final WindowPreferences preferences;
    private final JCheckBox shaping = new JCheckBox("Shape every link like radio");
    private final JTextField rates = new JTextField(40);
    private final JTextField delay = new JTextField(6);
    private final JTextField queue = new JTextField(6);
    private final JCheckBox airtime = new JCheckBox("A robot's links share its radio's airtime");
    private final JLabel message = new JLabel(" ");
    private final Color normalBackground = rates.getBackground();
    private boolean saved;

    /** Shows {@code values} (a value for each of the five keys); OK stores them in {@code preferences}. */
    LinkShapingDialog(Window owner, boolean editable, WindowPreferences preferences, Map<String, String> values) {
        super(owner, TITLE, ModalityType.APPLICATION_MODAL);
        this.editable = editable;
        this.preferences = preferences;
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);

        JPanel rows = DialogParts.titled(editable ? "For the next Start" : "Of the server that runs (Stop it to change them)");
        box(rows, 0, "Link shaping", shaping, ShapingConfig.SHAPING, "on".equalsIgnoreCase(values.get(ShapingConfig.SHAPING)),
                "Shape every link: rate and delay from the signal strength, a robot's airtime shared (wss.shaping, docs/shaping.md)");
        field(rows, 1, RATES_LABEL, rates, ShapingConfig.RATES, values.get(ShapingConfig.RATES), "dBm:rate, strongest first",
                RATES_HELP);
        field(rows, 2, DELAY_LABEL, delay, ShapingConfig.DELAY_MS, values.get(ShapingConfig.DELAY_MS), "ms, besides each byte's airtime",
                DELAY_HELP);
        box(rows, 3, "Shared airtime", airtime, ShapingConfig.AIRTIME, Boolean.parseBoolean(values.get(ShapingConfig.AIRTIME)),
                "Links sharing a robot share its radio's airtime, by time (wss.shaping.airtime)");
        field(rows, 4, QUEUE_LABEL, queue, ShapingConfig.QUEUE_MS, values.get(ShapingConfig.QUEUE_MS), "ms at the link's rate, beyond its delay",
                QUEUE_HELP);

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
        box.setName(key);
        box.setToolTipText(help);
        box.setSelected(selected);
        box.setEnabled(editable);
        panel.add(DialogParts.label(label, help, box), DialogParts.cell(0, y, 0, false));
        panel.add(box, DialogParts.cell(1, y, 4, true));
    }

    private void field(JPanel panel, int y, String label, JTextField field, String key, String value, String unit, String help) {
        field.setName(key);
        field.setText(value);
        field.setMinimumSize(field.getPreferredSize());
        field.getDocument().addDocumentListener(DialogParts.onChange(() -> {
            mark(field, help);
            message.setText(" "); // a refusal speaks of the values OK saw; the marks stay current
        }));
        mark(field, help);
        if (!editable) {
            DialogParts.readOnly(field);
        }
        JLabel units = new JLabel(unit);
        units.setToolTipText(help);
        units.setBorder(BorderFactory.createEmptyBorder(0, 6, 0, 0));
        JPanel beside = new JPanel(new FlowLayout(FlowLayout.LEADING, 0, 0)); // the unit right after a short field too
        beside.add(field);
        beside.add(units);
        panel.add(DialogParts.label(label, help, field), DialogParts.cell(0, y, 0, false));
        panel.add(beside, DialogParts.cell(1, y, 8, true));
    }

    /** Red with the reason as its tooltip while its value is refused; else its help. */
    private void mark(JTextField field, String help) {
        String problem = ShapingValues.problem(field.getName(), field.getText());
        field.setBackground(problem != null ? DialogParts.INVALID : normalBackground);
        field.setToolTipText(problem != null ? problem : help);
    }

    private void ok() {
        Map<String, String> values = new LinkedHashMap<>();
        values.put(ShapingConfig.SHAPING, shaping.isSelected() ? "on" : "off");
        values.put(ShapingConfig.RATES, rates.getText().strip());
        values.put(ShapingConfig.DELAY_MS, delay.getText().strip());
        values.put(ShapingConfig.AIRTIME, String.valueOf(airtime.isSelected()));
        values.put(ShapingConfig.QUEUE_MS, queue.getText().strip());
        List<JTextField> refused = new ArrayList<>();
        String first = null;
        for (JTextField field : List.of(rates, delay, queue)) {
            String problem = ShapingValues.problem(field.getName(), field.getText());
            if (problem != null) {
                first = first != null ? first : LABELS.get(field.getName()) + ": " + problem;
                refused.add(field);
            }
        }
        if (first != null) {
            DialogParts.showMessage(message, first + (refused.size() > 1 ? " (and " + (refused.size() - 1) + " more marked)" : ""));
            refused.get(0).requestFocusInWindow();
            return;
        }
        try {
            preferences.storeShaping(values);
        } catch (BackingStoreException | RuntimeException e) {
            DialogParts.showMessage(message, "Cannot save the settings: " + e.getMessage());
            return;
        }
        saved = true;
        dispose();
    }
}
