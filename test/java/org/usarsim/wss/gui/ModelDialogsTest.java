package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Window;
import java.util.List;
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
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.WssEventListener;

class ModelDialogsTest {

    /** A model that records what the dialogs do to it. */
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

    @Test
    void theBuiltInModelsAreConfigurable() {
        assertTrue(ModelDialogs.isConfigurable(new Recorder("DistanceOnlyPropagationModel", false)));
        assertTrue(ModelDialogs.isConfigurable(new Recorder("ObstaclePropagationModel", false)));
        assertTrue(ModelDialogs.isConfigurable(new Recorder("MyModel", true)));
        assertFalse(ModelDialogs.isConfigurable(new Recorder("NoopPropagationModel", false)));
    }

    @Test
    void aBuiltInModelGetsTheDialogAndOkConfiguresIt() throws Exception {
        Recorder model = new Recorder("DistanceOnlyPropagationModel", false);
        CompletableFuture<Boolean> shown = show(model, true);
        Window dialog = dialog("DistanceOnlyPropagationModel Configuration");
        assertFalse(shown.isDone(), "modal: show() waits for the dialog");
        Gui.run(() -> Gui.find(dialog, JTextField.class, "usarsim.port").setText("7440"));
        Gui.run(() -> Gui.find(dialog, JButton.class, DistanceModelDialog.OK).doClick());

        assertTrue(shown.get(5, TimeUnit.SECONDS));
        assertEquals("7440", preferences.load("DistanceOnlyPropagationModel").get("usarsim.port"));
        assertEquals(7440, model.configured.getInt("usarsim.port", -1));
        assertEquals(preferences.load("DistanceOnlyPropagationModel"), model.configured.asMap());
        assertNull(model.dialogEditable, "not the model's own dialog");
    }

    @Test
    void cancelLeavesTheModelAlone() throws Exception {
        Recorder model = new Recorder("ObstaclePropagationModel", false);
        CompletableFuture<Boolean> shown = show(model, true);
        Window dialog = dialog("ObstaclePropagationModel Configuration");
        Gui.run(() -> Gui.find(dialog, JButton.class, DistanceModelDialog.CANCEL).doClick());
        assertFalse(shown.get(5, TimeUnit.SECONDS));
        assertNull(model.configured);
        assertEquals(0, root.node("ObstaclePropagationModel").keys().length);
    }

    @Test
    void readOnlyWhileTheServerRuns() throws Exception {
        Recorder model = new Recorder("DistanceOnlyPropagationModel", false);
        CompletableFuture<Boolean> shown = show(model, false);
        Window dialog = dialog("DistanceOnlyPropagationModel Configuration");
        List<String> buttons = Gui.onEdt(() -> Gui.all(dialog, JButton.class).stream().map(JButton::getName).toList());
        assertEquals(List.of(DistanceModelDialog.CLOSE), buttons);
        Gui.run(() -> Gui.find(dialog, JButton.class, DistanceModelDialog.CLOSE).doClick());
        assertFalse(shown.get(5, TimeUnit.SECONDS));
        assertNull(model.configured);
    }

    @Test
    void anyOtherModelShowsItsOwnDialog() throws Exception {
        Recorder model = new Recorder("MyModel", true);
        assertFalse(show(model, true).get(5, TimeUnit.SECONDS));
        assertEquals(Boolean.TRUE, model.dialogEditable);
        Recorder running = new Recorder("MyModel", true);
        assertFalse(show(running, false).get(5, TimeUnit.SECONDS));
        assertEquals(Boolean.FALSE, running.dialogEditable);
        assertNull(model.configured);
    }
}
