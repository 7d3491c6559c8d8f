package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.WindowEvent;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.prefs.Preferences;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.model.simulator.SimulatorModel;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;

/** The dialog for real: a window on a display (xvfb-run under CI), driven from the test's thread. */
@Tag("slow")
class DistanceModelDialogTest {

    /** The preferences nodes of the real models the dialogs are opened for. */
    private static final String DISTANCE = "DistanceOnlyPropagationModel";
    private static final String OBSTACLE = "ObstaclePropagationModel";
    private static final PropagationModel DISTANCE_MODEL = new DistanceOnlyPropagationModel();
    private static final PropagationModel OBSTACLE_MODEL = new ObstaclePropagationModel();

    /** The keys the DistanceOnly dialog shows; the Obstacle dialog adds the obstacle.* keys. */
    private static final List<String> DISTANCE_KEYS = List.of("positions", "positions.interval", "usarsim.host", "usarsim.port",
            "usarsim.timeout", "rosbridge.url", "rosbridge.topic", "rosbridge.type", "rosbridge.frame", "rosbridge.names",
            "rosbridge.stale", "rosbridge.grace", "rosbridge.maxMessage", "distance.cutoff", "distance.n", "distance.pd0", "distance.d0",
            "distance.margin", "distance.holdTime", "shadowing.sigma", "shadowing.distance");

    /** Four decimals, as the fields show computed values. */
    private static final double FOUR_DECIMALS = 0.5e-4 + 1e-9;

    private Preferences root;
    private ModelPreferences preferences;
    private DistanceModelDialog dialog;

    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @BeforeEach
    void setUp() {
        root = TestPreferences.create();
        preferences = new ModelPreferences(root);
    }

    @AfterEach
    void tearDown() throws Exception {
        if (dialog != null) {
            Gui.run(() -> dialog.dispose());
        }
        TestPreferences.remove(root);
    }

    // ---- helpers ----

    /** Opens the modal dialog without blocking the test: shown from invokeLater, then driven from here. */
    private DistanceModelDialog open(SimulatorModel model, boolean editable) {
        dialog = Gui.onEdt(() -> new DistanceModelDialog(null, model, editable, preferences, preferences.load(model)));
        SwingUtilities.invokeLater(() -> dialog.setVisible(true));
        Gui.until("the dialog shows", () -> dialog.isShowing());
        return dialog;
    }

    private JTextField field(String name) {
        return Gui.onEdt(() -> Gui.find(dialog, JTextField.class, name));
    }

    private String text(String name) {
        JTextField field = field(name);
        return Gui.onEdt(field::getText);
    }

    private double number(String name) {
        return Double.parseDouble(text(name));
    }

    private void type(String name, String value) {
        JTextField field = field(name);
        Gui.run(() -> field.setText(value));
    }

    private void click(String name) {
        JButton button = Gui.onEdt(() -> Gui.find(dialog, JButton.class, name));
        Gui.run(button::doClick);
    }

    private String label(String name) {
        return Gui.onEdt(() -> Gui.find(dialog, JLabel.class, name).getText());
    }

    /** The note beside the cutoff distance, as plain text (its tooltip, which says it in full). */
    private String note() {
        JLabel note = Gui.onEdt(() -> Gui.find(dialog, JLabel.class, DistanceModelDialog.RANGE_NOTE));
        return Gui.onEdt(() -> note.getToolTipText() != null ? note.getToolTipText() : note.getText());
    }

    /**
     * Whether a label shows its whole text in the room it has: a plain text no wider, an HTML one
     * wrapped within its width to no more lines than its height holds. Event thread.
     */
    static boolean whole(JLabel label) {
        java.awt.Insets insets = label.getInsets();
        int width = label.getWidth() - insets.left - insets.right;
        int height = label.getHeight() - insets.top - insets.bottom;
        javax.swing.text.View html = (javax.swing.text.View) label.getClientProperty(javax.swing.plaf.basic.BasicHTML.propertyKey);
        if (html == null) {
            return label.getFontMetrics(label.getFont()).stringWidth(label.getText()) <= width;
        }
        html.setSize(width, height);
        return html.getMinimumSpan(javax.swing.text.View.X_AXIS) <= width && html.getPreferredSpan(javax.swing.text.View.Y_AXIS) <= height;
    }

    private void waitClosed() {
        Gui.until("the dialog is closed", () -> !dialog.isDisplayable());
    }

    private static double distance(double cutoff, double pd0, double n, double d0) {
        return d0 * Math.pow(10, (pd0 - cutoff) / (10 * n));
    }

    private static double exponent(double cutoff, double pd0, double d0, double distance) {
        return (pd0 - cutoff) / (10 * Math.log10(distance / d0));
    }

    // ---- what it shows ----

    @Test
    void opensWithTheDefaultsAndTheirCutoffDistance() {
        open(new DistanceOnlyPropagationModel(), true);
        assertEquals("DistanceOnlyPropagationModel Configuration", Gui.onEdt(dialog::getTitle));
        assertTrue(Gui.onEdt(dialog::isModal));
        for (String key : DISTANCE_KEYS) {
            assertEquals(Setting.defaults(DISTANCE_MODEL.settings()).get(key), text(key), key);
        }
        // 2 * 10^(43.33 / 10): about 43055.6 m
        assertEquals(distance(-93, -49.67, 1, 2), number(DistanceModelDialog.CUTOFF_DISTANCE), FOUR_DECIMALS);
        assertEquals(" ", label(DistanceModelDialog.MESSAGE));
    }

    @Test
    void theDistanceDialogHasNoObstacleFieldsAndTheObstacleDialogHasThem() {
        open(new DistanceOnlyPropagationModel(), true);
        List<String> names = Gui.onEdt(() -> Gui.all(dialog, JTextField.class).stream().map(f -> f.getName()).toList());
        List<String> expected = new java.util.ArrayList<>(DISTANCE_KEYS);
        expected.add(DistanceModelDialog.CUTOFF_DISTANCE);
        assertEquals(expected.stream().sorted().toList(), names.stream().sorted().toList());
        Gui.run(() -> dialog.dispose());

        open(new ObstaclePropagationModel(), true);
        assertEquals("ObstaclePropagationModel Configuration", Gui.onEdt(dialog::getTitle));
        assertEquals("6.325", text("obstacle.attenuation"));
        assertEquals("1.0", text("obstacle.cacheDistance"));
        assertEquals("", text("obstacle.walls"));
        assertEquals("/map", text("rosbridge.map"));
        assertEquals(distance(-93, -49.67, 1, 2), number(DistanceModelDialog.CUTOFF_DISTANCE), FOUR_DECIMALS);
    }

    @Test
    void showsTheStoredValues() throws Exception {
        preferences.store(OBSTACLE_MODEL, Map.of("usarsim.host", "10.1.2.3", "distance.n", "2.5", "obstacle.attenuation", "4"));
        open(new ObstaclePropagationModel(), true);
        assertEquals("10.1.2.3", text("usarsim.host"));
        assertEquals("2.5", text("distance.n"));
        assertEquals("4", text("obstacle.attenuation"));
        assertEquals(distance(-93, -49.67, 2.5, 2), number(DistanceModelDialog.CUTOFF_DISTANCE), FOUR_DECIMALS);
    }

    // ---- the cutoff distance, both ways ----

    @Test
    void editingAParameterRecomputesTheDistance() {
        open(new DistanceOnlyPropagationModel(), true);
        type("distance.n", "2");
        assertEquals(distance(-93, -49.67, 2, 2), number(DistanceModelDialog.CUTOFF_DISTANCE), FOUR_DECIMALS);
        type("distance.pd0", "-40");
        assertEquals(distance(-93, -40, 2, 2), number(DistanceModelDialog.CUTOFF_DISTANCE), FOUR_DECIMALS);
        type("distance.d0", "1.5");
        assertEquals(distance(-93, -40, 2, 1.5), number(DistanceModelDialog.CUTOFF_DISTANCE), FOUR_DECIMALS);
        type("distance.cutoff", "-85.5");
        assertEquals(distance(-85.5, -40, 2, 1.5), number(DistanceModelDialog.CUTOFF_DISTANCE), FOUR_DECIMALS);
    }

    @Test
    void editingTheDistanceRecomputesN() {
        open(new DistanceOnlyPropagationModel(), true);
        type(DistanceModelDialog.CUTOFF_DISTANCE, "55.6");
        double n = exponent(-93, -49.67, 2, 55.6);
        assertEquals(n, number("distance.n"), FOUR_DECIMALS);
        assertEquals("55.6", text(DistanceModelDialog.CUTOFF_DISTANCE), "the typed distance stays as typed");
        assertEquals(" ", label(DistanceModelDialog.RANGE_NOTE));
        // and back: the N shown gives the distance typed
        assertEquals(55.6, distance(-93, -49.67, number("distance.n"), 2), 0.01);
    }

    @Test
    void aCutoffAbovePd0GivesADistanceWithinD0() {
        open(new DistanceOnlyPropagationModel(), true);
        type("distance.cutoff", "-40");
        // 2 * 10^(-9.67 / 10): about 0.2157 m
        assertEquals(distance(-40, -49.67, 1, 2), number(DistanceModelDialog.CUTOFF_DISTANCE), FOUR_DECIMALS);
        assertTrue(number(DistanceModelDialog.CUTOFF_DISTANCE) < 2);
        assertTrue(label(DistanceModelDialog.RANGE_NOTE).contains("within d0"), label(DistanceModelDialog.RANGE_NOTE));
        assertNotEquals(DistanceModelDialog.INVALID, Gui.onEdt(field(DistanceModelDialog.CUTOFF_DISTANCE)::getBackground));

        type("distance.cutoff", "-49.67");
        assertEquals("2", text(DistanceModelDialog.CUTOFF_DISTANCE), "exactly d0 when Cutoff = Pd0");
        assertTrue(label(DistanceModelDialog.RANGE_NOTE).contains("any N"), label(DistanceModelDialog.RANGE_NOTE));
    }

    @Test
    void aDistanceWithinD0IsAcceptedWhenTheCutoffIsAbovePd0() throws Exception {
        open(new DistanceOnlyPropagationModel(), true);
        type("distance.cutoff", "-40");
        type(DistanceModelDialog.CUTOFF_DISTANCE, "0.5");
        assertEquals(exponent(-40, -49.67, 2, 0.5), number("distance.n"), FOUR_DECIMALS);
        assertEquals("0.5", text(DistanceModelDialog.CUTOFF_DISTANCE), "the typed distance stays as typed");
        assertEquals(" ", label(DistanceModelDialog.RANGE_NOTE));
        assertNotEquals(DistanceModelDialog.INVALID, Gui.onEdt(field(DistanceModelDialog.CUTOFF_DISTANCE)::getBackground));
        // and back: the N shown gives the distance typed
        assertEquals(0.5, distance(-40, -49.67, number("distance.n"), 2), 0.001);

        String n = text("distance.n");
        click(DistanceModelDialog.OK);
        waitClosed();
        assertEquals(n, preferences.load(DISTANCE_MODEL).get("distance.n"));
        assertEquals("-40", preferences.load(DISTANCE_MODEL).get("distance.cutoff"));
    }

    @Test
    void aDistanceNoNGivesIsRefusedAndTheDialogSaysWhy() {
        open(new DistanceOnlyPropagationModel(), true);
        // {cutoff, pd0, typed distance, why}; d0 is 2 and N is 1 throughout
        String[][] refused = {
            {"-93", "-49.67", "1.5", "with Cutoff below Pd0 it must be beyond d0 (2 m)"},
            {"-93", "-49.67", "2", "it is d0, which needs Cutoff = Pd0"},
            {"-40", "-49.67", "3", "with Cutoff above Pd0 it must be within d0 (2 m)"},
            {"-40", "-49.67", "2", "it is d0, which needs Cutoff = Pd0"},
            {"-49.67", "-49.67", "3", "with Cutoff = Pd0 it is d0 (2 m)"},
            {"-49.67", "-49.67", "0.5", "with Cutoff = Pd0 it is d0 (2 m)"},
            {"-1e308", "1e308", "100", "N too large or too small for a double"},
        };
        for (String[] bad : refused) {
            String what = "cutoff " + bad[0] + ", Pd0 " + bad[1] + ", distance " + bad[2];
            type("distance.cutoff", bad[0]);
            type("distance.pd0", bad[1]);
            type(DistanceModelDialog.CUTOFF_DISTANCE, bad[2]);
            assertEquals("1", text("distance.n"), "N is not touched: " + what);
            assertEquals("no N > 0 gives this distance: " + bad[3], note(), what);
            assertEquals(DistanceModelDialog.INVALID, Gui.onEdt(field(DistanceModelDialog.CUTOFF_DISTANCE)::getBackground), what);
            // in full under the groups at once, as the note beside the field is cut short
            assertTrue(label(DistanceModelDialog.MESSAGE).contains("Cutoff distance (m): '" + bad[2] + "': no N > 0 gives this distance: "
                    + bad[3]), label(DistanceModelDialog.MESSAGE));
        }
        // OK refuses while no N gives the distance the user typed
        click(DistanceModelDialog.OK);
        assertTrue(Gui.onEdt(dialog::isShowing));
        assertTrue(label(DistanceModelDialog.MESSAGE).contains("Cutoff distance (m): '100': no N > 0 gives this distance"),
                label(DistanceModelDialog.MESSAGE));
        // a parameter edit recomputes the distance, and with it the problem is gone
        type("distance.pd0", "-49.67");
        type("distance.cutoff", "-93");
        type("distance.n", "2");
        assertEquals(distance(-93, -49.67, 2, 2), number(DistanceModelDialog.CUTOFF_DISTANCE), FOUR_DECIMALS);
        assertNotEquals(DistanceModelDialog.INVALID, Gui.onEdt(field(DistanceModelDialog.CUTOFF_DISTANCE)::getBackground));
        click(DistanceModelDialog.OK);
        waitClosed();
        assertEquals("2", preferences.load(DISTANCE_MODEL).get("distance.n"));
    }

    @Test
    void theObstacleDialogsNoteOnARefusedDistanceShowsWholeAndIsItsTooltip() {
        open(new ObstaclePropagationModel(), true);
        type("distance.cutoff", "-93");
        type("distance.pd0", "-49.67");
        type(DistanceModelDialog.CUTOFF_DISTANCE, "1.5");
        String why = "no N > 0 gives this distance: with Cutoff below Pd0 it must be beyond d0 (2 m)";
        assertEquals(why, note(), "the tooltip says it whole");
        JLabel note = Gui.onEdt(() -> Gui.find(dialog, JLabel.class, DistanceModelDialog.RANGE_NOTE));
        assertTrue(Gui.onEdt(() -> note.getText().contains(why)), Gui.onEdt(note::getText));
        assertTrue(Gui.onEdt(() -> whole(note)), "shown whole in " + Gui.onEdt(note::getSize));
    }

    @Test
    void theDistanceOfCutoffEqualToPd0IsD0ForAnyNAndTypingItKeepsN() {
        open(new DistanceOnlyPropagationModel(), true);
        type("distance.cutoff", "-49.67");
        type("distance.n", "2.5");
        type(DistanceModelDialog.CUTOFF_DISTANCE, "2");
        assertEquals("2.5", text("distance.n"));
        assertTrue(label(DistanceModelDialog.RANGE_NOTE).contains("any N"), label(DistanceModelDialog.RANGE_NOTE));
        assertNotEquals(DistanceModelDialog.INVALID, Gui.onEdt(field(DistanceModelDialog.CUTOFF_DISTANCE)::getBackground));
    }

    @Test
    void noDistanceWhileAParameterIsBad() {
        open(new DistanceOnlyPropagationModel(), true);
        type("distance.d0", "0");
        assertEquals("", text(DistanceModelDialog.CUTOFF_DISTANCE));
        assertEquals(DistanceModelDialog.INVALID, Gui.onEdt(field("distance.d0")::getBackground));
        type(DistanceModelDialog.CUTOFF_DISTANCE, "100");
        assertEquals("1", text("distance.n"));
        type("distance.d0", "3");
        assertEquals(distance(-93, -49.67, 1, 3), number(DistanceModelDialog.CUTOFF_DISTANCE), FOUR_DECIMALS);
    }

    // ---- OK, Cancel, read-only ----

    @Test
    void okStoresTheValues() throws Exception {
        open(new ObstaclePropagationModel(), true);
        type("usarsim.host", " 192.168.1.20 ");
        type("usarsim.port", "7436");
        type("positions.interval", "500");
        type("distance.margin", "3");
        type("distance.holdTime", "1.5");
        type("obstacle.cacheDistance", "0.5");
        type(DistanceModelDialog.CUTOFF_DISTANCE, "55.6");
        String n = text("distance.n");
        click(DistanceModelDialog.OK);
        waitClosed();
        assertTrue(dialog.saved());

        Map<String, String> stored = preferences.load(OBSTACLE_MODEL);
        assertEquals("192.168.1.20", stored.get("usarsim.host"));
        assertEquals("7436", stored.get("usarsim.port"));
        assertEquals("500", stored.get("positions.interval"));
        assertEquals("3", stored.get("distance.margin"));
        assertEquals("1.5", stored.get("distance.holdTime"));
        assertEquals("0.5", stored.get("obstacle.cacheDistance"));
        assertEquals(n, stored.get("distance.n"));
        assertEquals("-93", stored.get("distance.cutoff"));
        assertEquals(Map.of(), preferences.load(DISTANCE_MODEL).entrySet().stream()
                .filter(e -> !e.getValue().equals(Setting.defaults(DISTANCE_MODEL.settings()).get(e.getKey())))
                .collect(java.util.stream.Collectors.toMap(Map.Entry::getKey, Map.Entry::getValue)),
                "the other model's node is untouched");

        // opened again, it shows what was stored, and about the distance typed
        open(new ObstaclePropagationModel(), true);
        assertEquals("192.168.1.20", text("usarsim.host"));
        assertEquals(n, text("distance.n"));
        assertEquals(55.6, number(DistanceModelDialog.CUTOFF_DISTANCE), 0.01);
    }

    @Test
    void cancelStoresNothing() throws Exception {
        open(new DistanceOnlyPropagationModel(), true);
        type("usarsim.port", "7436");
        type(DistanceModelDialog.CUTOFF_DISTANCE, "55.6");
        click(DistanceModelDialog.CANCEL);
        waitClosed();
        assertFalse(dialog.saved());
        assertEquals(0, root.node(DISTANCE).keys().length);
        assertEquals(Setting.defaults(DISTANCE_MODEL.settings()), preferences.load(DISTANCE_MODEL));
    }

    @Test
    void closingTheWindowStoresNothing() throws Exception {
        open(new DistanceOnlyPropagationModel(), true);
        type("usarsim.port", "7436");
        Gui.run(() -> dialog.dispatchEvent(new WindowEvent(dialog, WindowEvent.WINDOW_CLOSING)));
        waitClosed();
        assertFalse(dialog.saved());
        assertEquals(0, root.node(DISTANCE).keys().length);
    }

    @Test
    void aBadValueIsRefusedAndTheDialogStaysOpen() throws Exception {
        open(new DistanceOnlyPropagationModel(), true);
        type("usarsim.port", "abc");
        type("usarsim.timeout", "50");
        click(DistanceModelDialog.OK);
        assertTrue(Gui.onEdt(dialog::isShowing));
        assertFalse(dialog.saved());
        String message = label(DistanceModelDialog.MESSAGE);
        assertTrue(message.contains("Port: 'abc' is not a port number from 1 to 65535"), message);
        assertTrue(message.contains("1 more"), "says another field is marked: " + message);
        assertEquals(DistanceModelDialog.INVALID, Gui.onEdt(field("usarsim.port")::getBackground));
        assertEquals(DistanceModelDialog.INVALID, Gui.onEdt(field("usarsim.timeout")::getBackground));
        assertNotEquals(DistanceModelDialog.INVALID, Gui.onEdt(field("usarsim.host")::getBackground));
        assertEquals(0, root.node(DISTANCE).keys().length, "nothing stored");

        type("usarsim.port", "7000");
        assertNotEquals(DistanceModelDialog.INVALID, Gui.onEdt(field("usarsim.port")::getBackground), "unmarked when fixed");
        assertEquals(" ", label(DistanceModelDialog.MESSAGE), "the refusal goes with the next edit");
        assertEquals(DistanceModelDialog.INVALID, Gui.onEdt(field("usarsim.timeout")::getBackground), "the other mark stays");
        click(DistanceModelDialog.OK);
        assertTrue(Gui.onEdt(dialog::isShowing));
        assertTrue(label(DistanceModelDialog.MESSAGE).contains("Timeout (ms): '50' is not a whole number of milliseconds"),
                label(DistanceModelDialog.MESSAGE));

        type("usarsim.timeout", "5000");
        click(DistanceModelDialog.OK);
        waitClosed();
        assertEquals("7000", preferences.load(DISTANCE_MODEL).get("usarsim.port"));
        assertEquals("5000", preferences.load(DISTANCE_MODEL).get("usarsim.timeout"));
    }

    @Test
    void everyRuleIsSettingsRule() {
        open(new ObstaclePropagationModel(), true);
        String[][] refused = {
            {"usarsim.host", "my host"}, {"usarsim.port", "0"}, {"positions.interval", "99"}, {"usarsim.timeout", "60001"},
            {"positions", "ros"}, {"rosbridge.type", "std_msgs/String"}, {"rosbridge.stale", "-1"}, {"rosbridge.maxMessage", "0"},
            {"distance.cutoff", "NaN"}, {"distance.n", "0"}, {"distance.pd0", "-49,67"}, {"distance.d0", "-2"},
            {"distance.margin", "-1"}, {"distance.holdTime", "1s"}, {"obstacle.attenuation", "-0.5"},
            {"obstacle.cacheDistance", "far"},
        };
        for (String[] bad : refused) {
            String before = text(bad[0]);
            type(bad[0], bad[1]);
            click(DistanceModelDialog.OK);
            assertTrue(Gui.onEdt(dialog::isShowing), bad[0] + " = " + bad[1]);
            assertTrue(label(DistanceModelDialog.MESSAGE).contains(Setting.find(OBSTACLE_MODEL.settings(), bad[0]).problem(bad[1])), label(DistanceModelDialog.MESSAGE));
            type(bad[0], before);
        }
        click(DistanceModelDialog.OK);
        waitClosed();
    }

    @Test
    void readOnlyHasEveryFieldDisabledAndOnlyClose() throws Exception {
        preferences.store(OBSTACLE_MODEL, Map.of("usarsim.port", "7001"));
        open(new ObstaclePropagationModel(), false);
        List<JTextField> fields = Gui.onEdt(() -> Gui.all(dialog, JTextField.class));
        assertEquals(DISTANCE_KEYS.size() + 8, fields.size(), "the Obstacles group's four, the Wall Materials' three and the cutoff distance");
        for (JTextField field : fields) {
            assertFalse(Gui.onEdt(field::isEnabled), field.getName() + " is enabled");
        }
        assertEquals("7001", text("usarsim.port"), "shows the values");
        List<String> buttons = Gui.onEdt(() -> Gui.all(dialog, JButton.class).stream().map(JButton::getText).toList());
        assertEquals(List.of("Close"), buttons);
        click(DistanceModelDialog.CLOSE);
        waitClosed();
        assertFalse(dialog.saved());
        assertEquals(List.of("usarsim.port"), List.of(root.node(OBSTACLE).keys()));
    }

    // ---- where the positions come from ----

    /** The title of the group holding a field. */
    private String groupTitle(String key) {
        JTextField field = field(key);
        return Gui.onEdt(() -> {
            for (java.awt.Container parent = field.getParent(); parent != null; parent = parent.getParent()) {
                if (parent instanceof javax.swing.JComponent group && group.getBorder() instanceof javax.swing.border.CompoundBorder border
                        && border.getOutsideBorder() instanceof javax.swing.border.TitledBorder titled) {
                    return titled.getTitle();
                }
            }
            return null;
        });
    }

    private boolean labelEnabled(String key) {
        JTextField field = field(key);
        return Gui.onEdt(() -> Gui.all(dialog, JLabel.class).stream().filter(l -> l.getLabelFor() == field).findFirst().orElseThrow()
                .isEnabled());
    }

    @Test
    void readOnlyTellsWhichSourceOfPositionsRuns() throws Exception {
        for (String source : List.of("usarsim", "rosbridge")) {
            preferences.store(OBSTACLE_MODEL, Map.of("positions", source));
            open(new ObstaclePropagationModel(), false);
            boolean usarsim = source.equals("usarsim");
            String used = usarsim ? "usarsim.host" : "rosbridge.url";
            String unused = usarsim ? "rosbridge.url" : "usarsim.host";
            assertEquals(usarsim ? "USARSim Connection" : "rosbridge", groupTitle(used), "the source that runs, " + source);
            assertEquals(usarsim ? "rosbridge (not used)" : "USARSim Connection (not used)", groupTitle(unused),
                    "the source that does not, " + source);
            for (String key : usarsim ? USARSIM_FIELDS : ROSBRIDGE_FIELDS) {
                assertTrue(labelEnabled(key), key + "'s label, used, " + source);
                assertEquals(DialogParts.READ_ONLY_TEXT, Gui.onEdt(field(key)::getDisabledTextColor), key + ", used, " + source);
            }
            List<String> notUsed = new java.util.ArrayList<>(usarsim ? ROSBRIDGE_FIELDS : USARSIM_FIELDS);
            if (usarsim) {
                notUsed.add("rosbridge.map");
            }
            for (String key : notUsed) {
                assertFalse(labelEnabled(key), key + "'s label, not used, " + source);
                assertNotEquals(DialogParts.READ_ONLY_TEXT, Gui.onEdt(field(key)::getDisabledTextColor), key + ", not used, " + source);
            }
            assertTrue(labelEnabled("distance.cutoff") && labelEnabled("positions.interval"), "the groups both use, " + source);
            Gui.run(() -> dialog.dispose());
        }
    }

    @Test
    void anEditableDialogsGroupTitleFollowsPositions() {
        open(new DistanceOnlyPropagationModel(), true);
        assertEquals("rosbridge (not used)", groupTitle("rosbridge.url"));
        assertEquals("USARSim Connection", groupTitle("usarsim.host"));
        type("positions", "rosbridge");
        assertEquals("rosbridge", groupTitle("rosbridge.url"));
        assertEquals("USARSim Connection (not used)", groupTitle("usarsim.host"));
        type("positions", "ros");
        assertEquals("rosbridge", groupTitle("rosbridge.url"), "while it names neither");
        assertEquals("USARSim Connection", groupTitle("usarsim.host"), "while it names neither");
    }

    private static final List<String> USARSIM_FIELDS = List.of("usarsim.host", "usarsim.port", "usarsim.timeout");
    private static final List<String> ROSBRIDGE_FIELDS = List.of("rosbridge.url", "rosbridge.topic", "rosbridge.type",
            "rosbridge.frame", "rosbridge.names", "rosbridge.stale", "rosbridge.grace", "rosbridge.maxMessage");

    /** Whether each field, and the label naming it, is enabled; a greyed field on the grey of one that cannot be edited. */
    private void assertEnabled(List<String> keys, boolean enabled, String when) {
        for (String key : keys) {
            JTextField field = field(key);
            assertEquals(enabled, Gui.onEdt(field::isEnabled), key + " enabled " + when);
            JLabel label = Gui.onEdt(() -> Gui.all(dialog, JLabel.class).stream()
                    .filter(l -> l.getLabelFor() == field).findFirst().orElseThrow());
            assertEquals(enabled, Gui.onEdt(label::isEnabled), key + "'s label enabled " + when);
            if (!enabled) {
                assertEquals(Gui.onEdt(DialogParts::readOnlyBackground), Gui.onEdt(field::getBackground), key + "'s background " + when);
            }
        }
    }

    @Test
    void theFieldsOfTheSourceNotChosenAreGreyedAsPositionsChanges() {
        for (PropagationModel model : List.of(DISTANCE_MODEL, OBSTACLE_MODEL)) {
            open((SimulatorModel) model, true);
            List<String> rosbridge = new java.util.ArrayList<>(ROSBRIDGE_FIELDS);
            List<String> always = new java.util.ArrayList<>(List.of("positions", "positions.interval", "distance.cutoff",
                    "distance.n", "distance.pd0", "distance.d0", "distance.margin", "distance.holdTime"));
            if (model == OBSTACLE_MODEL) {
                rosbridge.add("rosbridge.map");
                always.addAll(List.of("obstacle.attenuation", "obstacle.cacheDistance", "obstacle.walls"));
            }
            assertEnabled(USARSIM_FIELDS, true, "with positions = usarsim, the default");
            assertEnabled(rosbridge, false, "with positions = usarsim, the default");
            type("positions", "rosbridge");
            assertEnabled(USARSIM_FIELDS, false, "with positions = rosbridge");
            assertEnabled(rosbridge, true, "with positions = rosbridge");
            type("positions", "ros");
            assertEnabled(USARSIM_FIELDS, true, "while positions names neither");
            assertEnabled(rosbridge, true, "while positions names neither");
            type("positions", " usarsim ");
            assertEnabled(USARSIM_FIELDS, true, "with positions = usarsim again");
            assertEnabled(rosbridge, false, "with positions = usarsim again");
            assertEnabled(always, true, "whatever positions says");
            Gui.run(() -> dialog.dispose());
        }
    }

    @Test
    void aStoredRosbridgeGreysTheUsarsimFieldsAndAGreyedRefusedValueSaysHowToEditIt() throws Exception {
        preferences.store(DISTANCE_MODEL, Map.of("positions", "rosbridge"));
        open(new DistanceOnlyPropagationModel(), true);
        assertEnabled(USARSIM_FIELDS, false, "with positions = rosbridge stored");
        assertEnabled(ROSBRIDGE_FIELDS, true, "with positions = rosbridge stored");
        type("rosbridge.stale", "-1");
        assertEquals(DistanceModelDialog.INVALID, Gui.onEdt(field("rosbridge.stale")::getBackground));
        type("positions", "usarsim");
        assertEquals(DistanceModelDialog.INVALID, Gui.onEdt(field("rosbridge.stale")::getBackground), "refused, greyed or not");
        click(DistanceModelDialog.OK);
        assertTrue(Gui.onEdt(dialog::isShowing));
        assertTrue(label(DistanceModelDialog.MESSAGE).startsWith("<html>Stale limit (ms): '-1' is not "), label(DistanceModelDialog.MESSAGE));
        assertTrue(label(DistanceModelDialog.MESSAGE).endsWith("(greyed: set Positions from to rosbridge to edit it)</html>"),
                label(DistanceModelDialog.MESSAGE));
        type("positions", "rosbridge");
        type("rosbridge.stale", "0");
        type("positions", "usarsim");
        click(DistanceModelDialog.OK);
        waitClosed();
        assertEquals("usarsim", preferences.load(DISTANCE_MODEL).get("positions"));
        assertEquals("0", preferences.load(DISTANCE_MODEL).get("rosbridge.stale"), "a greyed field's value is stored");
    }

    // ---- numbers ----

    @Test
    void computedNumbersHaveAtMostFourDecimalsAndAPointWhateverTheLocale() {
        Locale before = Locale.getDefault();
        try {
            Locale.setDefault(Locale.GERMANY);
            assertEquals("43055.6347", CutoffDistance.format(43055.634744));
            assertEquals("3.0007", CutoffDistance.format(3.000712));
            assertEquals("2", CutoffDistance.format(2.0000001));
            assertEquals("0", CutoffDistance.format(-0.00001 * 0));
            assertEquals("-93.5", CutoffDistance.format(-93.5));
            // what four decimals would show as 0, and the very large: exponent notation, still a number
            assertEquals(1.23457e-5, Double.parseDouble(CutoffDistance.format(0.0000123456789)), 1e-10);
            assertTrue(Double.parseDouble(CutoffDistance.format(0.0000123456789)) > 0);
            assertEquals(1.23457e43, Double.parseDouble(CutoffDistance.format(1.234567e43)), 1e38);
        } finally {
            Locale.setDefault(before);
        }
    }

    @Test
    void theDialogsFormulasArePathLossRangeAndItsInverse() {
        PathLoss defaults = new PathLoss(-49.67, 1, 2, -93);
        assertEquals(2 * Math.pow(10, 43.33 / 10), defaults.range(), 1e-9);
        assertEquals(1, PathLoss.exponentFor(-49.67, 2, -93, defaults.range()), 1e-12);
        PathLoss above = new PathLoss(-49.67, 2.5, 2, -40);
        assertTrue(above.range() < 2, "a cutoff above Pd0: within d0");
        assertEquals(2.5, PathLoss.exponentFor(-49.67, 2, -40, above.range()), 1e-12);
        assertEquals(2, new PathLoss(-50, 3, 2, -50).range(), "a cutoff equal to Pd0: d0");
        // no N above 0 gives these
        double[][] none = {
            {-49.67, 2, -93, 1.5}, {-49.67, 2, -93, 2}, {-49.67, 2, -40, 3}, {-49.67, 2, -40, 2},
            {-50, 2, -50, 3}, {-50, 2, -50, 2}, {1e308, 2, -1e308, 100}, {-49.67, 2, -93, 0}, {-49.67, 2, -93, -5},
        };
        for (double[] c : none) {
            assertTrue(Double.isNaN(PathLoss.exponentFor(c[0], c[1], c[2], c[3])), Arrays.toString(c));
        }
    }
}
