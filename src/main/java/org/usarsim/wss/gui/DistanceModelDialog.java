package org.usarsim.wss.gui;

import java.awt.Color;
import java.awt.Window;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import org.usarsim.wss.model.DialogLayout;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.simulator.SimulatorModel;

/**
 * The configuration dialog of the models whose {@code dialogLayout()} is {@link DialogLayout#DISTANCE}
 * or {@link DialogLayout#DISTANCE_AND_OBSTACLES} (DistanceOnlyPropagationModel and
 * ObstaclePropagationModel, or a plugin that asks for it), laid out as the original's (its
 * manual's figure 2) with groups it did not have: "Positions" (where they come from) and
 * "rosbridge" before its "USARSim Connection", "Link Stability" and, for
 * {@code DISTANCE_AND_OBSTACLES}, "Obstacles". The values are those of the model's preferences node, named by its {@code name()}. Fields hold the model keys' values as
 * text; each field's label, unit, tooltip and check come from the model's declared {@link Setting}s. The cutoff distance is derived, both ways
 * ({@link CutoffDistance}): editing Cutoff, N, Pd0 or d0 recomputes it, editing it recomputes N; the
 * groups are laid out by a {@link FieldGrid}. OK stores the values with
 * {@link ModelPreferences}; in read-only mode (the server runs) every field is disabled and the
 * only button is Close. Modal; build and show it on the Swing event thread.
 */
final class DistanceModelDialog extends ModelSettingsDialog {

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
    private static final String GRACE = "rosbridge.grace";
    private static final String MAX_MESSAGE = "rosbridge.maxMessage";
    private static final String CUTOFF = CutoffDistance.CUTOFF;
    private static final String N = CutoffDistance.N;
    private static final String PD0 = CutoffDistance.PD0;
    private static final String D0 = CutoffDistance.D0;
    private static final String MARGIN = "distance.margin";
    private static final String HOLD_TIME = "distance.holdTime";
    private static final String SHADOWING_SIGMA = "shadowing.sigma";
    private static final String SHADOWING_DISTANCE = "shadowing.distance";
    /** The keys of the groups every layout shows: the positions, their two sources, the signal, the link stability. */
    private static final List<String> DISTANCE_KEYS = List.of(POSITIONS, INTERVAL, HOST, PORT, TIMEOUT, URL, TOPIC, TYPE, FRAME,
            NAMES, STALE, GRACE, MAX_MESSAGE, CUTOFF, N, PD0, D0, MARGIN, HOLD_TIME, SHADOWING_SIGMA, SHADOWING_DISTANCE);
    private static final String ATTENUATION = "obstacle.attenuation";
    private static final String CACHE_DISTANCE = "obstacle.cacheDistance";
    private static final String WALLS = "obstacle.walls";
    private static final String MAP = "rosbridge.map";
    /** The Obstacle model's walls of its own by material (issue 35): shown when the model declares them. */
    private static final List<String> MATERIAL_KEYS = List.of("obstacle.materials", "obstacle.loss", "obstacle.heightBand");
    /** The titles of the groups of the two sources; the one {@code positions} does not name adds {@link #NOT_USED}. */
    static final String USARSIM_TITLE = "USARSim Connection";
    static final String ROSBRIDGE_TITLE = "rosbridge";
    static final String NOT_USED = " (not used)";
    /** The fields of one source of positions: greyed while {@code positions} names the other. */
    private static final List<String> USARSIM_KEYS = List.of(HOST, PORT, TIMEOUT);
    private static final List<String> ROSBRIDGE_KEYS = List.of(URL, TOPIC, TYPE, FRAME, NAMES, STALE, GRACE, MAX_MESSAGE, MAP);


    private final Map<String, CheckedField> fields = new LinkedHashMap<>();
    private final Map<String, Setting> rules = new LinkedHashMap<>();
    private final Map<String, JLabel> labels = new LinkedHashMap<>();
    private final FieldGrid grid = new FieldGrid();
    private final CutoffDistance distance;
    /** The groups of the two sources of positions, whose titles say which one is not used. */
    private final JPanel usarsimGroup;
    private final JPanel rosbridgeGroup;

    /** True while the dialog itself sets a field's text, so that its listener does not recompute. */
    private boolean updating;

    /**
     * Shows {@code values} (a value for each key the model declares); OK stores the values in
     * {@code model.name()}'s preferences. It does not touch the model itself.
     */
    DistanceModelDialog(Window owner, PropagationModel model, boolean editable, ModelPreferences preferences, Map<String, String> values) {
        super(owner, model, editable, preferences);
        this.distance = new CutoffDistance(this::parameter, n -> set(N, n), message);
        boolean obstacles = model.dialogLayout() == DialogLayout.DISTANCE_AND_OBSTACLES;

        usarsimGroup = group(USARSIM_TITLE, HOST, PORT, TIMEOUT);
        rosbridgeGroup = group(ROSBRIDGE_TITLE, URL, TOPIC, TYPE, FRAME, NAMES, STALE, GRACE, MAX_MESSAGE);
        List<JPanel> groups = new ArrayList<>(List.of(group("Positions", POSITIONS, INTERVAL), usarsimGroup, rosbridgeGroup,
                group("Signal Strength Computation Parameters", CUTOFF, N, PD0, D0), distance.panel(grid, obstacles),
                group("Link Stability", MARGIN, HOLD_TIME), group("Shadowing", SHADOWING_SIGMA, SHADOWING_DISTANCE)));
        if (obstacles) {
            groups.add(group("Obstacles", ATTENUATION, CACHE_DISTANCE, WALLS, MAP));
            if (MATERIAL_KEYS.stream().allMatch(key -> Setting.find(declared, key) != null)) {
                groups.add(group("Wall Materials", MATERIAL_KEYS.toArray(String[]::new)));
            }
        }
        grid.alignColumns();

        fields.keySet().forEach(key -> set(key, values.get(key)));
        distance.parametersChanged();
        if (!editable) {
            fields.values().forEach(field -> DialogParts.readOnly(field.field()));
            distance.readOnly();
        }
        followPositions();
        DialogParts.layOut(this, owner, groups, message, DialogParts.buttons(this, editable, this::ok));
    }

    /** A titled group of the fields of these keys, two to a row ({@link FieldGrid}). */
    private JPanel group(String title, String... keys) {
        List<JLabel> groupLabels = new ArrayList<>();
        List<JTextField> groupFields = new ArrayList<>();
        for (String key : keys) {
            Setting setting = rule(key);
            JTextField field = field(setting);
            JLabel label = DialogParts.label(setting.labelWithUnit(), setting.help(), field);
            labels.put(key, label);
            groupLabels.add(label);
            groupFields.add(field);
        }
        return grid.group(title, groupLabels, groupFields);
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
        boolean parameter = List.of(CUTOFF, N, PD0, D0).contains(setting.key());
        boolean positions = setting.key().equals(POSITIONS);
        CheckedField field = new CheckedField(new JTextField(setting.type() == Setting.Type.TEXT ? 16 : 10), setting.key(),
                setting.help(), setting::problem, message, () -> {
                    if (positions) {
                        followPositions();
                    }
                    if (parameter && !updating) {
                        distance.parametersChanged();
                    }
                });
        fields.put(setting.key(), field);
        rules.put(setting.key(), setting);
        return field.field();
    }

    /** Sets a field's text as the dialog's own doing: the cutoff distance is not recomputed from it. */
    private void set(String key, String text) {
        updating = true;
        fields.get(key).field().setText(text);
        updating = false;
    }

    /** A parameter's value, or null when its field does not hold an accepted one. */
    private Double parameter(String key) {
        CheckedField field = fields.get(key);
        return field.problem() == null ? Double.valueOf(field.text()) : null;
    }

    // ---- where the positions come from ----

    /**
     * Marks the source of positions that {@code positions} does not name as not used: its group's
     * title says "(not used)" and its labels are greyed, and so are its fields (the rosbridge ones
     * with the Obstacles group's Map topic while it says usarsim, the USARSim Connection ones while
     * it says rosbridge; none while it names neither, a value being typed). Read-only (the server
     * runs), where every field is disabled, the used source's values stay dark and the unused
     * one's take the look's pale disabled text, so that one can tell which source runs. Greyed
     * fields keep their values, which OK still checks and stores.
     */
    private void followPositions() {
        String positions = fields.get(POSITIONS).text();
        source(USARSIM_KEYS, usarsimGroup, USARSIM_TITLE, !positions.equals(SimulatorModel.ROSBRIDGE));
        source(ROSBRIDGE_KEYS, rosbridgeGroup, ROSBRIDGE_TITLE, !positions.equals(SimulatorModel.USARSIM));
    }

    private void source(List<String> keys, JPanel group, String title, boolean used) {
        for (String key : keys) {
            CheckedField field = fields.get(key);
            if (field != null) { // the Map topic: the Obstacles group only
                labels.get(key).setEnabled(used);
                if (editable) {
                    field.field().setEnabled(used);
                    field.mark();
                } else {
                    field.field().setDisabledTextColor(used ? DialogParts.READ_ONLY_TEXT : DialogParts.unusedText());
                }
            }
        }
        DialogParts.retitle(group, used ? title : title + NOT_USED);
    }

    // ---- OK ----

    private void ok() {
        Map<String, String> values = new LinkedHashMap<>();
        Refusals refused = new Refusals();
        for (Map.Entry<String, CheckedField> entry : fields.entrySet()) {
            CheckedField field = entry.getValue();
            String problem = field.mark();
            if (problem != null) {
                refused.add(field.field(), DialogParts.refusal(rules.get(entry.getKey()).labelWithUnit(), field.text(), problem)
                        + (field.field().isEnabled() ? "" : " (greyed: set Positions from to "
                                + (USARSIM_KEYS.contains(entry.getKey()) ? SimulatorModel.USARSIM : SimulatorModel.ROSBRIDGE)
                                + " to edit it)"));
            }
            values.put(entry.getKey(), field.text());
        }
        if (distance.refusal() != null) {
            refused.add(distance.field(), distance.refusal());
        }
        finish(refused, values);
    }
}
