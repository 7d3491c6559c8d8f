package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;

import java.awt.event.WindowEvent;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import java.util.prefs.Preferences;
import javax.swing.JFrame;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.model.ModelProvider;

/**
 * The main window as a window test opens it: on hubs of a configuration, with throw-away
 * preferences, its log handler on the root logger, the models given and one of them chosen;
 * {@link #close} closes it as a user does (the window's close) and waits for it, then removes
 * the handler and the preferences.
 */
final class OpenWindow implements AutoCloseable {

    final HubServers servers;
    final WindowLog windowLog;
    final JFrame frame;
    private final Preferences preferences;
    private final CountDownLatch closed = new CountDownLatch(1);

    OpenWindow(HubConfig config, List<ModelProvider> models, String model) throws Exception {
        servers = new HubServers(config);
        preferences = TestPreferences.create();
        windowLog = new WindowLog();
        Logger.getLogger("").addHandler(windowLog);
        frame = onEdt(() -> MainWindow.open(servers, models, new WindowPreferences(preferences.node("window")),
                new ModelPreferences(preferences.node("models")), windowLog, new Launch("0", model, false, null, false),
                closed::countDown).frame());
    }

    @Override
    public void close() throws Exception {
        run(() -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
        assertTrue(closed.await(10, TimeUnit.SECONDS), "the window closed");
        Logger.getLogger("").removeHandler(windowLog);
        TestPreferences.remove(preferences);
    }
}
