package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;

import java.awt.event.WindowEvent;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import java.util.prefs.Preferences;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JTextArea;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.gui.Gui;
import org.usarsim.wss.gui.Launch;
import org.usarsim.wss.gui.MainWindow;
import org.usarsim.wss.gui.ModelPreferences;
import org.usarsim.wss.gui.TestPreferences;
import org.usarsim.wss.gui.WindowLog;
import org.usarsim.wss.gui.WindowPreferences;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.replay.ReplayPropagationModel;

/** The window with the replay model: a bad recording's Start says why in a dialog, as any failed Start does. */
@Tag("slow")
class ReplayWindowTest {

    @TempDir
    Path dir;

    private Preferences preferences;
    private WindowLog windowLog;
    private JFrame frame;
    private final CountDownLatch closed = new CountDownLatch(1);

    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @AfterEach
    void close() throws Exception {
        if (frame != null) {
            run(() -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
            assertTrue(closed.await(10, TimeUnit.SECONDS), "the window closed");
        }
        if (windowLog != null) {
            Logger.getLogger("").removeHandler(windowLog);
        }
        if (preferences != null) {
            TestPreferences.remove(preferences);
        }
    }

    @Test
    void aBadRecordingIsSaidInADialogAndStartStaysStart() throws Exception {
        Path other = Files.writeString(dir.resolve("v2.rec"), "WSS-RECORDING 2\nwss 9.0\n", StandardCharsets.UTF_8);
        preferences = TestPreferences.create();
        windowLog = new WindowLog();
        Logger.getLogger("").addHandler(windowLog);
        Properties properties = new Properties();
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        WindowServers servers = new WindowServers(ConfigFile.of(properties, "test"));
        // As --config gives them: the file's model settings for this session's starts.
        Launch launch = new Launch("0", "ReplayPropagationModel", false,
                new ModelSettings(Map.of("replay.file", other.toString())), false);
        List<ModelProvider> providers = List.of(ModelProvider.of(NoopPropagationModel::new),
                ModelProvider.of(ReplayPropagationModel::new));
        frame = onEdt(() -> MainWindow.open(servers, providers, new WindowPreferences(preferences.node("window")),
                new ModelPreferences(preferences.node("models")), windowLog, launch, closed::countDown).frame());

        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        run(start::doClick);
        assertEquals("ReplayPropagationModel did not start: " + other + " is a recording of format version 2; this WSS reads version 1",
                Gui.closeMessage("WSS"));
        JTextArea log = onEdt(() -> find(frame.getContentPane(), JTextArea.class, "log"));
        until("the log says it", () -> log.getText().contains("WARNING: ReplayPropagationModel did not start"));
        assertEquals("Start", onEdt(start::getText));
    }
}
