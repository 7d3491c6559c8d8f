package org.usarsim.wss.hub;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.hub.core.Changes;
import org.usarsim.wss.hub.core.RobotSession;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.hub.tcp.PortSockets;
import org.usarsim.wss.hub.tcp.Switchboard;

/**
 * Applies what a step of the core decided: under the hub's lock the step's events are numbered
 * in the {@link Outbox} and its port work resolved to the ports' sockets and given a turn
 * ({@link #taken}); after the lock the socket work is done in the order of the turns, the port
 * memory's timers set, and the events delivered ({@link #apply}). Holds the sockets of each port
 * the core holds (guarded by the hub's lock).
 */
final class ChangeApplier {

    /** A port that could not listen again: the hub tells the core, as a step of its own. */
    interface ListenFailure {
        void failed(Changes.PortAction action, IOException e);
    }

    /** A step's changes as they are applied: its port work resolved to sockets, and its turn (0: no socket work). */
    record Applying(Changes changes, List<PortTask> portTasks, long turn) {
    }

    /** A port's socket work with the sockets it is for, resolved under the lock (a port forgotten later keeps its own). */
    record PortTask(Changes.PortAction action, PortSockets sockets) {
    }

    private final Outbox outbox;
    private final ForgetTimer forgetTimer;
    private final Switchboard switchboard;
    private final ListenFailure listenFailure;
    private final SocketTurns turns = new SocketTurns();
    private final Map<WssPort, PortSockets> sockets = new HashMap<>();

    ChangeApplier(Outbox outbox, ForgetTimer forgetTimer, Switchboard switchboard, ListenFailure listenFailure) {
        this.outbox = outbox;
        this.forgetTimer = forgetTimer;
        this.switchboard = switchboard;
        this.listenFailure = listenFailure;
    }

    /** Under the hub's lock: the sockets of a port the core just allocated. */
    void put(WssPort port, PortSockets portSockets) {
        sockets.put(port, portSockets);
    }

    /** Under the hub's lock: the port's sockets, or null. */
    PortSockets socketsOf(WssPort port) {
        return sockets.get(port);
    }

    /** Under the hub's lock: the step's events are numbered in the outbox, its port work resolved and given a turn. */
    Applying taken(Changes out) {
        outbox.append(out.events());
        if (!out.hasSocketWork()) {
            return new Applying(out, List.of(), 0);
        }
        List<PortTask> tasks = new ArrayList<>();
        for (Changes.PortAction action : out.portActions()) {
            PortSockets portSockets = action.work() == Changes.PortWork.RELEASE ? sockets.remove(action.port())
                    : sockets.get(action.port());
            if (portSockets != null) {
                tasks.add(new PortTask(action, portSockets));
            }
        }
        return new Applying(out, tasks, turns.take());
    }

    /**
     * After the lock: the socket work in the order the steps were taken (a break's port stops
     * before the resume that follows it listens again), then the port memory's timers, then the
     * events. Returns once this step's socket work is done: a break has stopped its ports.
     */
    void apply(Applying applying) {
        Changes changes = applying.changes();
        if (applying.turn() > 0) {
            turns.await(applying.turn());
            try {
                applying.portTasks().forEach(this::portWork);
                changes.closes().forEach(close -> close.link().close(close.reason()));
                changes.sessionsToClose().forEach(RobotSession::close);
            } finally {
                turns.done(applying.turn());
            }
        }
        changes.forgetLater().forEach(later -> forgetTimer.schedule(later.robot(), later.afterNs()));
        outbox.deliver();
    }

    private void portWork(PortTask task) {
        Changes.PortAction action = task.action();
        switch (action.work()) {
            case LISTEN -> {
                try {
                    task.sockets().listen(switchboard, action.epoch());
                } catch (IOException e) {
                    listenFailure.failed(action, e);
                }
            }
            case STOP -> task.sockets().stopListening();
            case RELEASE -> task.sockets().release();
        }
    }
}
