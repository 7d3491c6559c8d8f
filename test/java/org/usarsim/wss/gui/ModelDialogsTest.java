package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.Window;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.prefs.Preferences;
import javax.swing.JButton;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;

/**
 * Which dialog a model gets, by its type, and what the built-in one does to the real models:
 * constructing them is cheap (no thread, no socket until start()). What a model was configured
 * with shows in its start failure, which names the simulator's address, on a port nobody listens on.
 */
class ModelDialogsTest {

    /** A model of a plugin, not a simulator model: records what the dialogs do to it. */
    private static final class Recorder implements PropagationModel {
        private final String name;
        private final boolean configurable;
        volatile ModelSettings configured;
        volatile Boolean dialogEditable;

        Recorder(String name, boolean configurable) {
            this.name = name;
            this.configurable = configurable;
        }

        @Override
        public String name() {
            return name;
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

        @Override
        public void setRobotLinkModel(RobotLinkModel linkModel) {
        }

        @Override
        public void setEventListener(WssEventListener listener) {
        }

        @Override
        public void start() {
        }

        @Override
        public void shutdown() {
        }

        @Override
        public boolean isActive() {
            return false;
        }

        @Override
        public double getSignalStrengthForPair(String from, String to) {
            return 0;
        }

        @Override
        public boolean connectionIsPossibleForPair(String from, String to) {
            return true;
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
