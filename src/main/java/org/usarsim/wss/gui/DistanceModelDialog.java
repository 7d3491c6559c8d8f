package org.usarsim.wss.gui;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.GridBagConstraints;
import java.awt.Insets;
import java.awt.Window;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.prefs.BackingStoreException;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.UIManager;
import org.usarsim.wss.model.DialogLayout;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.model.simulator.SimulatorModel;

/**
 * The configuration dialog of the models whose {@code dialogLayout()} is {@link DialogLayout#DISTANCE}
 * or {@link DialogLayout#DISTANCE_AND_OBSTACLES} (DistanceOnlyPropagationModel and
 * ObstaclePropagationModel, or a plugin that asks for it), laid out as the original's (its
 * manual's figure 2) with groups it did not have: "Positions" (where they come from) and
 * "rosbridge" before its "USARSim Connection", "Link Stability" and, for
 * {@code DISTANCE_AND_OBSTACLES}, "Obstacles". The values are those of the model's preferences node, named by its {@code name()}. Fields hold the model keys' values as
 * text; each field's label, unit, tooltip and check come from the model's declared {@link Setting}s. The cutoff distance is derived, both ways:
 * editing Cutoff, N, Pd0 or d0 recomputes it, editing it recomputes N. OK stores the values with
 * {@link ModelPreferences}; in read-only mode (the server runs) every field is disabled and the
 * only button is Close. Modal; build and show it on the Swing event thread.
 */
final class DistanceModelDialog extends JDialog {

    /** Component names, for tests and accessibility tools; each value field is named by its key. */
    static final String CUTOFF_DISTANCE = "cutoffDistance";
    static final String RANGE_NOTE = "rangeNote";
    static final String MESSAGE = DialogParts.MESSAGE;
    static final String OK = DialogParts.OK;
    static final String CANCEL = DialogParts.CANCEL;
    static final String CLOSE = DialogParts.CLOSE;

    /** The background of a field whose value is refused. */
    static final Color INVALID = DialogParts.INVALID;

    /** The keys of the fields; each one's label, unit, tooltip and rule are the model's {@link Setting}. */
    private static final String POSITIONS = "positions";
    private static final String INTERVAL = "positions.interval";
    private static final String HOST = "usarsim.host";
    private static final String PORT = "usarsim.port";
    private static final String TIMEOUT = "usarsim.timeout";
    private static final String URL = "rosbridge.url";
    private static final String TOPIC = "rosbridge.topic";
    private static final String TYPE = "rosbridge.type";
    private static final String FRAME = "rosbridge.frame";
    private static final String NAMES = "rosbridge.names";
    private static final String STALE = "rosbridge.stale";
    private static final String MAX_MESSAGE = "rosbridge.maxMessage";
    /** The keys of the groups every layout shows: the positions, their two sources, the signal, the link stability. */
    private static final List<String> DISTANCE_KEYS = List.of(POSITIONS, INTERVAL, HOST, PORT, TIMEOUT, URL, TOPIC, TYPE, FRAME,
            NAMES, STALE, MAX_MESSAGE, "distance.cutoff", "distance.n", "distance.pd0", "distance.d0", "distance.margin",
            "distance.holdTime");
    private static final String CUTOFF = "distance.cutoff";
    private static final String N = "distance.n";
    private static final String PD0 = "distance.pd0";
    private static final String D0 = "distance.d0";
    private static final String MARGIN = "distance.margin";
    private static final String HOLD_TIME = "distance.holdTime";
    private static final String ATTENUATION = "obstacle.attenuation";
    private static final String CACHE_DISTANCE = "obstacle.cacheDistance";
    private static final String WALLS = "obstacle.walls";
    private static final String MAP = "rosbridge.map";
    /** The fields of one source of positions: greyed while {@code positions} names the other. */
    private static final List<String> USARSIM_KEYS = List.of(HOST, PORT, TIMEOUT);
    private static final List<String> ROSBRIDGE_KEYS = List.of(URL, TOPIC, TYPE, FRAME, NAMES, STALE, MAX_MESSAGE, MAP);

    private final PropagationModel model;
    private final List<Setting> declared;
    private final boolean obstacles;
    private final boolean editable;
    private final ModelPreferences preferences;

    private final Map<String, JTextField> fields = new LinkedHashMap<>();
    private final Map<String, Setting> rules = new LinkedHashMap<>();
    private final Map<String, JLabel> labels = new LinkedHashMap<>();
    private final JTextField distance = new JTextField(10);
    private final JLabel rangeNote = new JLabel(" ");
    private final JLabel message = new JLabel(" ");
    private final List<JLabel> leftLabels = new ArrayList<>();
    private final List<JLabel> rightLabels = new ArrayList<>();
    private final Color normalBackground = distance.getBackground();

    /** True while the dialog itself sets a field's text, so that its listener does not recompute. */
    private boolean updating;
    /** What is wrong with the distance the user typed, or null. */
    private String distanceProblem;
    private boolean saved;

    /**
     * Shows {@code values} (a value for each key the model declares); OK stores the values in
     * {@code model.name()}'s preferences. It does not touch the model itself.
     */
    DistanceModelDialog(Window owner, PropagationModel model, boolean editable, ModelPreferences preferences, Map<String, String> values) {
        super(owner, model.name() + " Configuration", ModalityType.APPLICATION_MODAL);
        this.model = model;
        this.declared = model.settings();
        this.obstacles = model.dialogLayout() == DialogLayout.DISTANCE_AND_OBSTACLES;
        this.editable = editable;
        this.preferences = preferences;
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);

        List<JPanel> groups = new ArrayList<>(List.of(group("Positions", POSITIONS, INTERVAL),
                group("USARSim Connection", HOST, PORT, TIMEOUT),
                group("rosbridge", URL, TOPIC, TYPE, FRAME, NAMES, STALE, MAX_MESSAGE),
                group("Signal Strength Computation Parameters", CUTOFF, N, PD0, D0), distanceGroup(),
                group("Link Stability", MARGIN, HOLD_TIME)));
        if (obstacles) {
            groups.add(group("Obstacles", ATTENUATION, CACHE_DISTANCE, WALLS, MAP));
        }
        alignColumns();

        updating = true;
        fields.forEach((key, field) -> field.setText(values.get(key)));
        updating = false;
        showDistance();
        followPositions();
        if (!editable) {
            fields.values().forEach(DialogParts::readOnly);
            DialogParts.readOnly(distance);
        }
        DialogParts.layOut(this, owner, groups, message, DialogParts.buttons(this, editable, this::ok));
    }

    /** Whether OK stored the values. */
    boolean saved() {
        return saved;
    }

    // ---- layout ----

    /**
     * A titled group of fields, two to a row: label, field, label, field, then a filler that takes
     * any extra width. Fields keep their width, labels get the same width in every group
     * ({@link #alignColumns}), so the columns line up from group to group.
     */
    private JPanel group(String title, String... keys) {
        JPanel panel = DialogParts.titled(title);
        for (int i = 0; i < keys.length; i++) {
            int row = i / 2;
            boolean left = i % 2 == 0;
            Setting setting = rule(keys[i]);
            JTextField field = field(setting);
            JLabel label = DialogParts.label(setting.labelWithUnit(), setting.help(), field);
            (left ? leftLabels : rightLabels).add(label);
            labels.put(keys[i], label);
            panel.add(label, cell(left ? 0 : 2, row, left ? 0 : 18));
            panel.add(field, cell(left ? 1 : 3, row, 6));
        }
        panel.add(new JLabel(), filler());
        return panel;
    }

    private JPanel distanceGroup() {
        JPanel panel = DialogParts.titled("Easy Parameter Setting by Cutoff Distance");
        String tip = "The distance at which the signal strength falls to the cutoff"
                + (obstacles ? " with no obstacle in between" : "")
                + ": d0 * 10^((Pd0 - Cutoff) / (10 N)). Editing it recomputes N.";
        distance.setName(CUTOFF_DISTANCE);
        distance.setToolTipText(tip);
        distance.getDocument().addDocumentListener(DialogParts.onChange(this::distanceEdited));
        JLabel label = DialogParts.label("Cutoff distance (m)", tip, distance);
        leftLabels.add(label);
        rangeNote.setName(RANGE_NOTE);
        panel.add(label, cell(0, 0, 0));
        panel.add(distance, cell(1, 0, 6));
        // The note takes the rest of the row and never widens it: a long one is cut, not the field.
        GridBagConstraints note = cell(2, 0, 18);
        note.gridwidth = 3;
        note.weightx = 1;
        note.fill = GridBagConstraints.HORIZONTAL;
        rangeNote.setPreferredSize(new Dimension(1, rangeNote.getPreferredSize().height));
        rangeNote.setMinimumSize(rangeNote.getPreferredSize());
        panel.add(rangeNote, note);
        keepWidth(distance);
        return panel;
    }

    private static GridBagConstraints cell(int x, int y, int leftInset) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = x;
        c.gridy = y;
        c.anchor = GridBagConstraints.LINE_START;
        c.insets = new Insets(3, leftInset, 3, 0);
        return c;
    }

    private static GridBagConstraints filler() {
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = 4;
        c.gridy = 0;
        c.weightx = 1;
        return c;
    }

    /** Every group gets the same label widths, so that the fields line up from group to group. */
    private void alignColumns() {
        for (List<JLabel> column : List.of(leftLabels, rightLabels)) {
            int width = column.stream().mapToInt(label -> label.getPreferredSize().width).max().orElse(0);
            column.forEach(label -> label.setPreferredSize(new Dimension(width, label.getPreferredSize().height)));
        }
    }

    /**
     * Whether this dialog is the one for the model: it asks for it ({@code dialogLayout()}) and
     * declares every key the layout shows. A plugin's simulator model that changed the
     * declaration gets the dialog built from it instead.
     */
    static boolean fits(PropagationModel model) {
        DialogLayout layout = model.dialogLayout();
        if (layout != DialogLayout.DISTANCE && layout != DialogLayout.DISTANCE_AND_OBSTACLES) {
            return false;
        }
        List<String> keys = new ArrayList<>(DISTANCE_KEYS);
        if (layout == DialogLayout.DISTANCE_AND_OBSTACLES) {
            keys.addAll(List.of(ATTENUATION, CACHE_DISTANCE, WALLS, MAP));
        }
        List<Setting> declared = model.settings();
        return keys.stream().allMatch(key -> Setting.find(declared, key) != null);
    }

    /** The model's declaration of a key this dialog shows. */
    private Setting rule(String key) {
        Setting setting = Setting.find(declared, key);
        if (setting == null) {
            throw new IllegalStateException(model.name() + " does not declare " + key);
        }
        return setting;
    }

    private JTextField field(Setting setting) {
        JTextField field = new JTextField(setting.type() == Setting.Type.TEXT ? 16 : 10);
        field.setName(setting.key());
        field.setToolTipText(setting.help());
        keepWidth(field);
        fields.put(setting.key(), field);
        rules.put(setting.key(), setting);
        boolean parameter = List.of(CUTOFF, N, PD0, D0).contains(setting.key());
        boolean positions = setting.key().equals(POSITIONS);
        field.getDocument().addDocumentListener(DialogParts.onChange(() -> {
            mark(field, setting.problem(field.getText()) != null);
            if (positions) {
                followPositions();
            }
            if (!updating) {
                message.setText(" "); // a refusal speaks of the values OK saw; the marks stay current
                if (parameter) {
                    distanceProblem = null;
                    showDistance();
                }
            }
        }));
        return field;
    }

    /** A field is never squeezed below its width (GridBagLayout falls back to minimum sizes). */
    private static void keepWidth(JTextField field) {
        field.setMinimumSize(field.getPreferredSize());
    }

    /** Red while its value is refused, greyed or not; else white, or grey while greyed. */
    private void mark(JTextField field, boolean invalid) {
        field.setBackground(invalid ? INVALID : field.isEnabled() ? normalBackground : DialogParts.readOnlyBackground());
    }

    // ---- where the positions come from ----

    /**
     * Greys (disables) the fields, and their labels, of the source of positions that
     * {@code positions} does not name: the rosbridge ones (with the Obstacles group's Map topic)
     * while it says usarsim, the USARSim Connection ones while it says rosbridge; both stay
     * editable while it names neither (a value being typed). Greyed fields keep their values, which
     * OK still checks and stores.
     */
    private void followPositions() {
        if (!editable) {
            return; // every field is read-only already
        }
        String positions = fields.get(POSITIONS).getText().strip();
        enable(USARSIM_KEYS, !positions.equals(SimulatorModel.ROSBRIDGE));
        enable(ROSBRIDGE_KEYS, !positions.equals(SimulatorModel.USARSIM));
    }

    private void enable(List<String> keys, boolean enabled) {
        for (String key : keys) {
            JTextField field = fields.get(key);
            if (field != null) { // the Map topic: the Obstacles group only
                field.setEnabled(enabled);
                labels.get(key).setEnabled(enabled);
                mark(field, rules.get(key).problem(field.getText()) != null);
            }
        }
    }

    // ---- the cutoff distance, both ways ----

    /** A parameter's value, or null when its field does not hold an accepted one. */
    private Double parameter(String key) {
        String text = fields.get(key).getText();
        return rules.get(key).problem(text) == null ? Double.valueOf(text.strip()) : null;
    }

    /** distance = d0 * 10^((Pd0 - cutoff) / (10 N)) ({@link PathLoss#range}), shown after a parameter changed. */
    private void showDistance() {
        Double cutoff = parameter(CUTOFF);
        Double n = parameter(N);
        Double pd0 = parameter(PD0);
        Double d0 = parameter(D0);
        String text;
        String note;
        if (cutoff == null || n == null || pd0 == null || d0 == null) {
            text = "";
            note = "needs valid Cutoff, N, Pd0, d0";
        } else {
            double value = new PathLoss(pd0, n, d0, cutoff).range();
            if (Double.isInfinite(value) || value == 0) {
                // Beyond a double: 10^x overflows to infinity, or underflows to 0.
                text = value == 0 ? "0" : "unlimited";
                note = "N too small to compute a distance";
            } else {
                text = format(value);
                note = cutoff > pd0 ? "Cutoff > Pd0: within d0"
                        : cutoff.doubleValue() == pd0 ? "Cutoff = Pd0: d0, any N" : " ";
            }
        }
        updating = true;
        distance.setText(text);
        updating = false;
        mark(distance, false);
        note(note, false);
    }

    /**
     * N = (Pd0 - cutoff) / (10 log10(distance / d0)) ({@link PathLoss#exponentFor}), after the user
     * edited the distance.
     */
    private void distanceEdited() {
        if (updating) {
            return;
        }
        message.setText(" ");
        Double cutoff = parameter(CUTOFF);
        Double pd0 = parameter(PD0);
        Double d0 = parameter(D0);
        double value = parseDistance(distance.getText());
        String remark = " ";
        if (Double.isNaN(value)) {
            distanceProblem = "not a number of metres above 0";
        } else if (cutoff == null || pd0 == null || d0 == null) {
            distanceProblem = "N needs valid Cutoff, Pd0, d0";
        } else if (cutoff.doubleValue() == pd0 && value == d0) {
            // Every N gives it: N keeps its value.
            distanceProblem = null;
            remark = "Cutoff = Pd0: d0, any N";
        } else {
            double n = PathLoss.exponentFor(pd0, d0, cutoff, value);
            distanceProblem = Double.isNaN(n) ? "no N > 0 gives this distance: " + why(cutoff, pd0, d0, value) : null;
            if (distanceProblem == null) {
                updating = true;
                fields.get(N).setText(format(n));
                updating = false;
            }
        }
        mark(distance, distanceProblem != null);
        note(distanceProblem == null ? remark : distanceProblem, distanceProblem != null);
        if (distanceProblem != null) {
            show(distanceRefusal()); // in full: the note beside the field is cut short
        }
    }

    private String distanceRefusal() {
        return "Cutoff distance (m): '" + distance.getText().strip() + "': " + distanceProblem;
    }

    /** Why no N above 0 gives the distance: the sides of d0 each cutoff allows. */
    private static String why(double cutoff, double pd0, double d0, double distance) {
        String metres = format(d0) + " m";
        if (cutoff == pd0) {
            return "with Cutoff = Pd0 it is d0 (" + metres + ")";
        }
        if (distance == d0) {
            return "it is d0, which needs Cutoff = Pd0";
        }
        if (cutoff < pd0 && distance < d0) {
            return "with Cutoff below Pd0 it must be beyond d0 (" + metres + ")";
        }
        if (cutoff > pd0 && distance > d0) {
            return "with Cutoff above Pd0 it must be within d0 (" + metres + ")";
        }
        return "N too large or too small for a double";
    }

    /** Beside the distance: why there is none, or what is wrong with the one typed (in red). */
    private void note(String text, boolean problem) {
        rangeNote.setText(text);
        rangeNote.setToolTipText(text.isBlank() ? null : text);
        rangeNote.setForeground(problem ? DialogParts.MESSAGE_COLOR : UIManager.getColor("Label.foreground"));
    }

    private static double parseDistance(String text) {
        try {
            double value = Double.parseDouble(text.strip());
            return Double.isFinite(value) && value > 0 ? value : Double.NaN;
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    /**
     * A computed value as the fields show it: at most four decimals, no trailing zeros, a point
     * as the decimal separator whatever the locale; exponent notation for the very large and for
     * what four decimals would show as 0.
     */
    static String format(double value) {
        double magnitude = Math.abs(value);
        if (value != 0 && (magnitude >= 1e9 || magnitude < 0.00005)) {
            return String.format(Locale.ROOT, "%.6g", value).replaceAll("\\.?0+e", "e");
        }
        String text = String.format(Locale.ROOT, "%.4f", value).replaceAll("\\.?0+$", "");
        return text.equals("-0") ? "0" : text;
    }

    // ---- OK ----

    private void ok() {
        Map<String, String> values = new LinkedHashMap<>();
        JTextField first = null;
        String refusal = null;
        int refused = 0;
        for (Map.Entry<String, JTextField> entry : fields.entrySet()) {
            String text = entry.getValue().getText().strip();
            String problem = rules.get(entry.getKey()).problem(text);
            mark(entry.getValue(), problem != null);
            if (problem != null) {
                refused++;
                if (first == null) {
                    first = entry.getValue();
                    refusal = DialogParts.refusal(rules.get(entry.getKey()).labelWithUnit(), text, problem)
                            + (first.isEnabled() ? "" : " (greyed: set Positions from to "
                                    + (USARSIM_KEYS.contains(entry.getKey()) ? SimulatorModel.USARSIM : SimulatorModel.ROSBRIDGE)
                                    + " to edit it)");
                }
            }
            values.put(entry.getKey(), text);
        }
        if (distanceProblem != null) {
            refused++;
            if (first == null) {
                first = distance;
                refusal = distanceRefusal();
            }
        }
        if (first != null) {
            show(refusal + (refused > 1 ? " (and " + (refused - 1) + " more marked)" : ""));
            first.requestFocusInWindow();
            return;
        }
        try {
            preferences.store(model, values);
        } catch (BackingStoreException | RuntimeException e) {
            show("Cannot save the settings: " + e.getMessage());
            return;
        }
        saved = true;
        dispose();
    }

    private void show(String text) {
        DialogParts.showMessage(message, text);
    }
}
