package org.usarsim.wss.gui;

import java.util.List;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.Version;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.WssEventListener;

/**
 * The window's own server as its {@link WindowSource}: the hub through a {@link NetworkView}, the
 * log through the {@link WindowLog}, the model's replay controls and the hub's force and release.
 * The window tells it when its server has started, is stopping and has stopped.
 */
final class LocalSource implements WindowSource {

    private static final Logger LOG = Logger.getLogger(LocalSource.class.getName());

    private final NetworkView view = new NetworkView();
    private final WindowLog windowLog;
    private Servers.Running running;
    private Replay replay;

    LocalSource(WindowLog windowLog) {
        this.windowLog = windowLog;
    }

    /** What a server the window starts tells of its events. */
    WssEventListener listener() {
        return view;
    }

    /** The server started: shown from now on. */
    void started(Servers.Running server) {
        running = server;
        view.attach(server, server.model());
        replay = replayOf(server.model());
    }

    /** The server is stopping: no more force, no replay. */
    void stopping() {
        running = null;
        replay = null;
    }

    /** The server stopped: the next poll shows nothing. */
    void stopped() {
        view.detach();
    }

    /** The model's replay controls, or null when it replays nothing (or fails to say). */
    private static Replay replayOf(PropagationModel model) {
        try {
            return model.replay().orElse(null);
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, model.name() + " failed to give its replay controls: " + e, e);
            return null;
        }
    }

    @Override
    public HubSnapshot poll() {
        return view.poll();
    }

    @Override
    public MapData pollMap() {
        return view.pollMap();
    }

    @Override
    public List<String> drainLog() {
        return windowLog.drain();
    }

    @Override
    public Replay replay() {
        return replay;
    }

    @Override
    public PairControls controls() {
        return running;
    }

    @Override
    public boolean offersForce() {
        return true;
    }

    @Override
    public boolean ownsServer() {
        return true;
    }

    @Override
    public String title() {
        return MainWindow.TITLE + " " + Version.current();
    }

    @Override
    public String banner() {
        return null;
    }

    @Override
    public void close() {
        view.close();
    }
}
