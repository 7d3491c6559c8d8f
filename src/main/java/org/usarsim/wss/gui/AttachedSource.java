package org.usarsim.wss.gui;

import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import javax.swing.SwingUtilities;
import org.usarsim.wss.attach.MonitorClient;
import org.usarsim.wss.attach.ServerView;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.model.Replay;

/**
 * A server the window is attached to (docs/monitor.md, "Attaching the window") as its
 * {@link WindowSource}: the tables and the map from the {@link MonitorClient}'s views, the server's
 * log lines, its replay, and with an operator's token the force menu as POST /api/force. Start /
 * Stop and the dialogs are the server's. A new view asks the window for a refresh at once (the
 * timer's 250 ms would add to a change's way to the table).
 */
final class AttachedSource implements WindowSource, PairControls {

    private final MonitorClient client;
    private final AtomicBoolean refreshAsked = new AtomicBoolean();
    private MapData map;
    private ServerView last;

    AttachedSource(MonitorClient client) {
        this.client = client;
    }

    /** Starts the client's stream; {@code refresh} runs on the event thread when something new is ready (coalesced). */
    void start(Runnable refresh) {
        client.start(() -> {
            if (!refreshAsked.getAndSet(true)) {
                SwingUtilities.invokeLater(() -> {
                    refreshAsked.set(false);
                    refresh.run();
                });
            }
        });
    }

    /** The server's model and control port, as the last view said (null before any). */
    ServerView last() {
        return last;
    }

    @Override
    public HubSnapshot poll() {
        ServerView view = client.takeView();
        if (view == null) {
            return null;
        }
        last = view;
        map = new MapData(view.robots().stream().map(robot -> new MapData.Robot(robot.name(), robot.position(), robot.range())).toList(),
                view.lines().stream().map(line -> new MapData.Line(line.first(), line.second(), line.state(), line.strength(), line.rate()))
                        .toList(),
                view.walls(), view.cutoff(), view.routes(), view.allRoutes());
        return view.hub();
    }

    @Override
    public MapData pollMap() {
        MapData taken = map;
        map = null;
        return taken;
    }

    @Override
    public List<String> drainLog() {
        return client.drainLog().stream().map(line -> WindowLog.line(line.level(), line.message())).toList();
    }

    @Override
    public Replay replay() {
        return client.replay();
    }

    @Override
    public PairControls controls() {
        return client.operator() ? this : null;
    }

    @Override
    public boolean offersForce() {
        return client.operator();
    }

    @Override
    public boolean ownsServer() {
        return false;
    }

    @Override
    public String title() {
        return MainWindow.TITLE + " - attached to " + client.server();
    }

    @Override
    public String banner() {
        return client.status(System.currentTimeMillis());
    }

    @Override
    public void close() {
        client.close();
    }

    /** POST /api/force, as FORCE on the control port: {@code {State Down|Up}}, a pin's rate and delay with it. */
    @Override
    public void force(String robotA, String robotB, Force force, RatePin pin) {
        String segments = pair(robotA, robotB) + " {State " + (force == Force.DOWN ? "Down" : "Up") + "}";
        if (pin != null && pin.bitsPerSecond() > 0) {
            segments += " {Rate " + pin.bitsPerSecond() + "}" + (pin.pinsDelay() ? " {Delay " + pin.delayMs() + "}" : "");
        }
        send(segments);
    }

    /** POST /api/force {@code {State Model}}. */
    @Override
    public void release(String robotA, String robotB) {
        send(pair(robotA, robotB) + " {State Model}");
    }

    private static String pair(String robotA, String robotB) {
        return "{Robot " + robotA + "} {Peer " + robotB + "}";
    }

    /** On the force menu's thread; a refusal is thrown, and the menu logs it. */
    private void send(String segments) {
        try {
            client.post("/api/force", segments);
        } catch (java.io.IOException e) {
            throw new IllegalStateException(e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        }
    }
}
