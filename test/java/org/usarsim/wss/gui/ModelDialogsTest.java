package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.Color;
import java.awt.Window;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.prefs.Preferences;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JLabel;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.model.DialogLayout;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PluginJars;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.StubModel;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;

/**
 * Which dialog a model gets, by what it says (never by its type or its name), and what the
 * built-in one does to the real models:
 * constructing them is cheap (no thread, no socket until start()). What a model was configured
 * with shows in its start failure, which names the simulator's address, on a port nobody listens on.
 */
@Tag("slow")
class ModelDialogsTest {

    /** A model of a plugin, not a simulator model: records what the dialogs do to it. */
    private static final class Recorder extends StubModel {
        private final String name;
        private final boolean configurable;
        private final List<Setting> settings;
        private final DialogLayout layout;
        volatile ModelSettings configured;
        volatile Boolean dialogEditable;

        Recorder(String name, boolean configurable) {
            this(name, configurable, List.of());
        }

        Recorder(String name, boolean configurable, List<Setting> settings) {
            this(name, configurable, settings, null);
        }

        /** With {@code layout} null, the SPI's default {@code dialogLayout()}. */
        Recorder(String name, boolean configurable, List<Setting> settings, DialogLayout layout) {
            this.name = name;
            this.configurable = configurable;
            this.settings = settings;
            this.layout = layout;
        }

        @Override
        public DialogLayout dialogLayout() {
            return layout == null ? super.dialogLayout() : layout;
        }

        @Override
        public String name() {
            return name;
        }

        @Override
        public List<Setting> settings() {
            return settings;
        }

        @Override
        public void configure(ModelSettings settings) {
            configured = settings;
        }

        @Override
        public boolean isConfigurable() {
            return configurable;
        }

        @Override
        public void showConfigurationDialog(boolean editable) {
            dialogEditable = editable;
        }

    }

    /** The server, for a model's start(); it is never reached here. */
    private static final class NoRobots implements RobotLinkModel {
        @Override
        public boolean breakConnectionsForPair(String robotA, String robotB) {
            return false;
        }

        @Override
        public boolean resumeConnectionsForPair(String robotA, String robotB) {
            return false;
        }

        @Override
        public void kickOutRobot(String robot) {
        }

        @Override
        public List<String> getListOfRegisteredRobots() {
            return List.of();
        }
    }

    private Preferences root;
    private ModelPreferences preferences;

    @TempDir
    static Path plugins;

    /** The plugin models, compiled and jarred at test time as an author would: Tuned declares two settings. */
    private static ModelCatalog catalog;

    @BeforeAll
    static void display() throws IOException {
        Gui.requireDisplay();
        Path classes = PluginJars.compile(plugins);
        PluginJars.tunedJar(plugins.resolve("jars").resolve("tuned.jar"), classes);
        catalog = ModelCatalog.load(ModelDialogsTest.class.getClassLoader(), List.of(plugins.resolve("jars")));
    }

    @BeforeEach
    void setUp() {
        root = TestPreferences.create();
        preferences = new ModelPreferences(root);
    }

    @AfterEach
    void tearDown() throws Exception {
        Gui.run(() -> {
            for (Window window : Window.getWindows()) {
                window.dispose();
            }
        });
        TestPreferences.remove(root);
    }

    /** Calls show() on the event thread, as the window will; it returns when the dialog closes. */
    private CompletableFuture<Boolean> show(PropagationModel model, boolean editable) {
        CompletableFuture<Boolean> result = new CompletableFuture<>();
        SwingUtilities.invokeLater(() -> {
            try {
                result.complete(ModelDialogs.show(null, model, editable, preferences));
            } catch (Throwable e) {
                result.completeExceptionally(e);
            }
        });
        return result;
    }

    private static Window dialog(String title) {
        Gui.until("the dialog " + title + " shows", () -> Gui.showing(title).size() == 1);
        return Gui.onEdt(() -> Gui.showing(title).get(0));
    }

    /** Ports on 127.0.0.1 that were free a moment ago: bound at once on port 0, noted, closed. */
    private static int[] closedPorts(int count) throws IOException {
        List<ServerSocket> sockets = new ArrayList<>();
        try {
            for (int i = 0; i < count; i++) {
                ServerSocket socket = new ServerSocket();
                sockets.add(socket);
                socket.bind(new InetSocketAddress(InetAddress.getByName("127.0.0.1"), 0));
            }
            return sockets.stream().mapToInt(ServerSocket::getLocalPort).toArray();
        } finally {
            for (ServerSocket socket : sockets) {
                socket.close();
            }
        }
    }

    /** The model's start() fails for want of a simulator at 127.0.0.1:port: the port it was configured with. */
    private static void assertStartFailsNaming(PropagationModel model, int port) {
        model.setRobotLinkModel(new NoRobots());
        try {
            model.start();
            model.shutdown();
            fail(model.name() + " started: something listens on " + port);
        } catch (ModelStartException e) {
            assertTrue(e.getMessage().startsWith("cannot reach the simulator at 127.0.0.1:" + port + " ("), e.getMessage());
        }
    }

    private static void type(Window dialog, String field, String text) {
        Gui.run(() -> Gui.find(dialog, JTextField.class, field).setText(text));
    }

    private static void click(Window dialog, String button) {
        Gui.run(() -> Gui.find(dialog, JButton.class, button).doClick());
    }

    private static boolean hasField(Window dialog, String name) {
        return Gui.onEdt(() -> Gui.all(dialog, JTextField.class).stream().anyMatch(f -> name.equals(f.getName())));
    }

    // ---- which dialog ----

    @Test
    void theSimulatorModelsAreConfigurableAndAnyOtherWhenItSaysSo() {
        assertTrue(ModelDialogs.isConfigurable(new DistanceOnlyPropagationModel()));
        assertTrue(ModelDialogs.isConfigurable(new ObstaclePropagationModel()));
        assertTrue(ModelDialogs.isConfigurable(new MySimulatorModel()));
        assertTrue(ModelDialogs.isConfigurable(new Recorder("MyModel", true)));
        assertFalse(ModelDialogs.isConfigurable(new NoopPropagationModel()));
        assertFalse(ModelDialogs.isConfigurable(new Recorder("DistanceOnlyPropagationModel", false)), "a name is not a type");
    }

    @Test
    void theDistanceOnlyModelGetsTheDialogAndOkConfiguresIt() throws Exception {
        DistanceOnlyPropagationModel model = new DistanceOnlyPropagationModel();
        int port = closedPorts(1)[0];
        CompletableFuture<Boolean> shown = show(model, true);
        Window dialog = dialog("DistanceOnlyPropagationModel Configuration");
        assertFalse(shown.isDone(), "modal: show() waits for the dialog");
        assertFalse(hasField(dialog, "obstacle.attenuation"), "no Obstacles group");
        type(dialog, "usarsim.port", String.valueOf(port));
        click(dialog, DistanceModelDialog.OK);

        assertTrue(shown.get(5, TimeUnit.SECONDS));
        assertEquals(String.valueOf(port), preferences.load(model).get("usarsim.port"));
        assertStartFailsNaming(model, port);
    }

    @Test
    void theObstacleModelGetsTheObstaclesGroupAndCancelLeavesItAlone() throws Exception {
        int[] ports = closedPorts(2);
        ObstaclePropagationModel model = new ObstaclePropagationModel();
        model.configure(new ModelSettings(Map.of("usarsim.port", String.valueOf(ports[0]))));
        CompletableFuture<Boolean> shown = show(model, true);
        Window dialog = dialog("ObstaclePropagationModel Configuration");
        assertTrue(hasField(dialog, "obstacle.attenuation"));
        assertTrue(hasField(dialog, "obstacle.cacheDistance"));
        type(dialog, "usarsim.port", String.valueOf(ports[1]));
        click(dialog, DistanceModelDialog.CANCEL);

        assertFalse(shown.get(5, TimeUnit.SECONDS));
        assertEquals(0, root.node("ObstaclePropagationModel").keys().length);
        assertStartFailsNaming(model, ports[0]);
    }

    @Test
    void theRfCommsModelGetsTheGeneratedDialogWithItsPresetAndParameters() throws Exception {
        org.usarsim.wss.model.rfcomms.RfCommsPropagationModel model = new org.usarsim.wss.model.rfcomms.RfCommsPropagationModel();
        CompletableFuture<Boolean> shown = show(model, true);
        Window dialog = dialog("RFComms Configuration");
        for (String key : List.of("rfcomms.txPower", "rfcomms.capacity", "rfcomms.maxRange", "usarsim.port")) {
            assertTrue(hasField(dialog, key), key);
        }
        assertFalse(hasField(dialog, "distance.pd0"), "not RFComms'");
        assertFalse(hasField(dialog, "wss.seed"), "the run's seed, not the model's");
        type(dialog, "rfcomms.txPower", "20");
        click(dialog, DialogParts.OK);
        assertTrue(shown.get(5, TimeUnit.SECONDS));
        assertEquals("20", preferences.load(model).get("rfcomms.txPower"));
    }

    @Test
    void readOnlyWhileTheServerRuns() throws Exception {
        DistanceOnlyPropagationModel model = new DistanceOnlyPropagationModel();
        CompletableFuture<Boolean> shown = show(model, false);
        Window dialog = dialog("DistanceOnlyPropagationModel Configuration");
        List<String> buttons = Gui.onEdt(() -> Gui.all(dialog, JButton.class).stream().map(JButton::getName).toList());
        assertEquals(List.of(DistanceModelDialog.CLOSE), buttons);
        click(dialog, DistanceModelDialog.CLOSE);
        assertFalse(shown.get(5, TimeUnit.SECONDS));
        assertEquals(0, root.node("DistanceOnlyPropagationModel").keys().length);
    }

    @Test
    void anyOtherSimulatorModelGetsTheDialogUnderItsOwnName() throws Exception {
        MySimulatorModel model = new MySimulatorModel();
        int port = closedPorts(1)[0];
        CompletableFuture<Boolean> shown = show(model, true);
        Window dialog = dialog("MySimulatorModel Configuration");
        assertFalse(hasField(dialog, "obstacle.attenuation"), "no Obstacles group");
        type(dialog, "usarsim.port", String.valueOf(port));
        click(dialog, DistanceModelDialog.OK);

        assertTrue(shown.get(5, TimeUnit.SECONDS));
        assertEquals(String.valueOf(port), preferences.load(model).get("usarsim.port"));
        assertEquals(0, root.node("DistanceOnlyPropagationModel").keys().length);
        assertStartFailsNaming(model, port);
    }

    @Test
    void anyOtherModelShowsItsOwnDialogWhateverItsName() throws Exception {
        for (String name : List.of("MyModel", "DistanceOnlyPropagationModel")) {
            Recorder model = new Recorder(name, true);
            assertFalse(show(model, true).get(5, TimeUnit.SECONDS));
            assertEquals(Boolean.TRUE, model.dialogEditable, name);
            Recorder running = new Recorder(name, true);
            assertFalse(show(running, false).get(5, TimeUnit.SECONDS));
            assertEquals(Boolean.FALSE, running.dialogEditable, name);
            assertNull(model.configured, name);
        }
        assertTrue(Gui.onEdt(() -> Gui.showing("DistanceOnlyPropagationModel Configuration").isEmpty()));
    }

    // ---- the dialog built from a model's declared settings ----

    private static PropagationModel tuned() {
        PropagationModel model = catalog.find("Tuned");
        assertNotNull(model, "the plugin loaded: " + catalog.names());
        return model;
    }

    private static String message(Window dialog) {
        return Gui.onEdt(() -> Gui.find(dialog, JLabel.class, DialogParts.MESSAGE).getText());
    }

    private static Color background(Window dialog, String field) {
        return Gui.onEdt(() -> Gui.find(dialog, JTextField.class, field).getBackground());
    }

    @Test
    void aPluginsDeclaredSettingsGetAGeneratedDialogThatChecksStoresAndConfigures() throws Exception {
        PropagationModel model = tuned();
        assertTrue(ModelDialogs.isConfigurable(model));
        CompletableFuture<Boolean> shown = show(model, true);
        Window dialog = dialog("Tuned Configuration");
        assertFalse(shown.isDone(), "modal: show() waits for the dialog");
        // a labelled field per setting, its default in it, the unit beside it, the help as tooltip
        assertEquals("3", Gui.onEdt(() -> Gui.find(dialog, JTextField.class, "tuned.level").getText()));
        assertEquals("2.5", Gui.onEdt(() -> Gui.find(dialog, JTextField.class, "tuned.gain").getText()));
        assertEquals("Taken off the level's strength", Gui.onEdt(() -> Gui.find(dialog, JTextField.class, "tuned.gain").getToolTipText()));
        List<String> labels = Gui.onEdt(() -> Gui.all(dialog, JLabel.class).stream().map(JLabel::getText).toList());
        assertTrue(labels.containsAll(List.of("Level", "Gain", "dB")), labels.toString());

        // a bad value is refused with the rule's words, marked red, and nothing is stored or configured
        type(dialog, "tuned.level", "11");
        assertEquals(DialogParts.INVALID, background(dialog, "tuned.level"), "marked as it is typed");
        click(dialog, DialogParts.OK);
        assertTrue(Gui.onEdt(dialog::isShowing));
        assertTrue(message(dialog).contains("Level: '11' is not a whole number from 1 to 10"), message(dialog));
        type(dialog, "tuned.gain", "-1");
        click(dialog, DialogParts.OK);
        assertTrue(message(dialog).contains("Level: '11' is not a whole number from 1 to 10 (and 1 more marked)"), message(dialog));
        type(dialog, "tuned.level", "5");
        click(dialog, DialogParts.OK);
        assertTrue(message(dialog).contains("Gain (dB): '-1' is not a number of dB, 0 or more"), message(dialog));
        assertEquals(0, root.node("Tuned").keys().length, "nothing stored");
        assertEquals(-32.5, model.getSignalStrengthForPair("A", "B"), 0, "not configured");

        // good values: stored under the model's name and handed to configure
        type(dialog, "tuned.gain", " 0.25 ");
        assertNotEquals(DialogParts.INVALID, background(dialog, "tuned.gain"));
        click(dialog, DialogParts.OK);
        assertTrue(shown.get(5, TimeUnit.SECONDS));
        assertEquals(Map.of("tuned.level", "5", "tuned.gain", "0.25"), preferences.load(model));
        assertEquals("5", root.node("Tuned").get("tuned.level", null));
        assertEquals(-50.25, model.getSignalStrengthForPair("A", "B"), 0, "configured: -10 * 5 - 0.25");
    }

    @Test
    void theGeneratedDialogIsReadOnlyWhileTheServerRuns() throws Exception {
        PropagationModel model = tuned();
        preferences.store(model, Map.of("tuned.level", "7"));
        CompletableFuture<Boolean> shown = show(model, false);
        Window dialog = dialog("Tuned Configuration");
        List<String> buttons = Gui.onEdt(() -> Gui.all(dialog, JButton.class).stream().map(JButton::getName).toList());
        assertEquals(List.of(DialogParts.CLOSE), buttons);
        assertEquals("7", Gui.onEdt(() -> Gui.find(dialog, JTextField.class, "tuned.level").getText()), "the stored value");
        assertFalse(Gui.onEdt(() -> Gui.all(dialog, JTextField.class).stream().anyMatch(JTextField::isEnabled)));
        // Issue 26, item 6: it does not look editable either: not an editable field's white.
        assertFalse(Gui.onEdt(() -> Gui.find(dialog, JTextField.class, "tuned.level").getBackground()
                .equals(new JTextField().getBackground())), "a read-only field's background is not an editable one's");
        click(dialog, DialogParts.CLOSE);
        assertFalse(shown.get(5, TimeUnit.SECONDS));
        assertEquals(List.of("tuned.level"), List.of(root.node("Tuned").keys()));
    }

    /** Issue 26, item 6: the replay model's recording has a Browse button, usable only while the dialog edits. */
    @Test
    void theReplaysRecordingHasABrowseButtonThatEditsOnlyForTheNextStart() throws Exception {
        for (boolean editable : new boolean[] {true, false}) {
            CompletableFuture<Boolean> shown = show(new org.usarsim.wss.replay.ReplayPropagationModel(), editable);
            Window dialog = dialog("ReplayPropagationModel Configuration");
            JButton browse = Gui.onEdt(() -> Gui.find(dialog, JButton.class, "replay.fileBrowse"));
            assertEquals("Browse...", Gui.onEdt(browse::getText));
            assertEquals(editable, Gui.onEdt(browse::isEnabled));
            click(dialog, editable ? DialogParts.CANCEL : DialogParts.CLOSE);
            assertFalse(shown.get(5, TimeUnit.SECONDS));
        }
    }

    @Test
    void aBooleanSettingIsACheckBoxAndAModelsOwnDialogWinsOverTheGeneratedOne() throws Exception {
        List<Setting> settings = List.of(Setting.bool("my.loud", "Loud", false).help("Shout"),
                Setting.text("my.greeting", "Greeting", "hello"));
        Recorder model = new Recorder("Checked", false, settings);
        assertTrue(ModelDialogs.isConfigurable(model), "declared settings make a model configurable");
        CompletableFuture<Boolean> shown = show(model, true);
        Window dialog = dialog("Checked Configuration");
        JCheckBox box = Gui.onEdt(() -> Gui.find(dialog, JCheckBox.class, "my.loud"));
        assertFalse(Gui.onEdt(box::isSelected));
        Gui.run(box::doClick);
        type(dialog, "my.greeting", "   ");
        click(dialog, DialogParts.OK);
        assertTrue(message(dialog).contains("Greeting: '' is not some text"), message(dialog));
        type(dialog, "my.greeting", "hi");
        click(dialog, DialogParts.OK);
        assertTrue(shown.get(5, TimeUnit.SECONDS));
        assertEquals(Map.of("my.loud", "true", "my.greeting", "hi"), model.configured.asMap());

        Recorder own = new Recorder("Own", true, settings);
        assertFalse(show(own, true).get(5, TimeUnit.SECONDS));
        assertEquals(Boolean.TRUE, own.dialogEditable, "its own dialog");
        assertTrue(Gui.onEdt(() -> Gui.showing("Own Configuration").isEmpty()));
    }

    @Test
    void aSimulatorModelWithADeclarationOfItsOwnGetsTheGeneratedDialog() throws Exception {
        MySimulatorModel model = new MySimulatorModel("Reshaped", List.of(Setting.host("usarsim.host", "Host", "127.0.0.1"),
                Setting.integer("reshaped.rate", "Rate", 2).from(1).to(5).unit("Hz")));
        CompletableFuture<Boolean> shown = show(model, true);
        Window dialog = dialog("Reshaped Configuration");
        assertFalse(hasField(dialog, DistanceModelDialog.CUTOFF_DISTANCE), "not the DistanceOnly dialog: it lacks distance.*");
        type(dialog, "reshaped.rate", "4");
        click(dialog, DialogParts.OK);
        assertTrue(shown.get(5, TimeUnit.SECONDS));
        assertEquals(Map.of("usarsim.host", "127.0.0.1", "reshaped.rate", "4"), preferences.load(model));
        assertFalse(ModelDialogs.isConfigurable(new MySimulatorModel("Bare", List.of())), "no settings, no dialog of its own");
    }

    @Test
    void aPluginModelThatAsksForTheDistanceLayoutGetsItAndOneThatDoesNotGetsTheGeneratedDialog() throws Exception {
        List<Setting> distanceKeys = new DistanceOnlyPropagationModel().settings();
        List<Setting> obstacleKeys = new ObstaclePropagationModel().settings();
        assertEquals(DialogLayout.GENERATED, new Recorder("Plain", false).dialogLayout(), "the SPI's default");

        // Not a SimulatorModel, and not named like one: it says which layout it wants.
        Recorder asks = new Recorder("Ranged", false, distanceKeys, DialogLayout.DISTANCE);
        int port = closedPorts(1)[0];
        CompletableFuture<Boolean> shown = show(asks, true);
        Window dialog = dialog("Ranged Configuration");
        assertTrue(hasField(dialog, DistanceModelDialog.CUTOFF_DISTANCE), "the DistanceOnly layout");
        assertFalse(hasField(dialog, "obstacle.attenuation"), "no Obstacles group");
        type(dialog, "usarsim.port", String.valueOf(port));
        click(dialog, DistanceModelDialog.OK);
        assertTrue(shown.get(5, TimeUnit.SECONDS));
        assertEquals(String.valueOf(port), asks.configured.asMap().get("usarsim.port"), "stored and handed to configure");

        Recorder obstacles = new Recorder("Walled", false, obstacleKeys, DialogLayout.DISTANCE_AND_OBSTACLES);
        shown = show(obstacles, true);
        Window obstacleDialog = dialog("Walled Configuration");
        assertTrue(hasField(obstacleDialog, DistanceModelDialog.CUTOFF_DISTANCE));
        assertTrue(hasField(obstacleDialog, "obstacle.attenuation"), "the Obstacles group");
        click(obstacleDialog, DistanceModelDialog.CANCEL);
        assertFalse(shown.get(5, TimeUnit.SECONDS));

        // The same keys without asking, or asking without the keys the layout shows: the generated dialog.
        for (Recorder generated : List.of(new Recorder("Quiet", false, distanceKeys),
                new Recorder("Short", false, distanceKeys, DialogLayout.DISTANCE_AND_OBSTACLES))) {
            shown = show(generated, true);
            Window plain = dialog(generated.name() + " Configuration");
            assertFalse(hasField(plain, DistanceModelDialog.CUTOFF_DISTANCE), generated.name());
            assertTrue(hasField(plain, "distance.cutoff"), generated.name() + ": a row per declared setting");
            click(plain, DialogParts.CANCEL);
            assertFalse(shown.get(5, TimeUnit.SECONDS));
        }
    }

    // ---- before every start ----

    @Test
    void configureFromPreferencesHandsTheModelItsStoredValues() throws Exception {
        int[] ports = closedPorts(2);
        preferences.store(new ObstaclePropagationModel(), Map.of("usarsim.port", String.valueOf(ports[0])));
        preferences.store(new DistanceOnlyPropagationModel(), Map.of("usarsim.port", String.valueOf(ports[1])));
        ObstaclePropagationModel model = new ObstaclePropagationModel();
        ModelDialogs.configureFromPreferences(model, preferences);
        assertStartFailsNaming(model, ports[0]);

        Recorder nothingStored = new Recorder("MyModel", false);
        ModelDialogs.configureFromPreferences(nothingStored, preferences);
        assertEquals(Map.of(), nothingStored.configured.asMap(), "it declares no setting");
    }
}
