package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetAddress;
import java.nio.channels.ServerSocketChannel;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import org.usarsim.wss.hub.core.Changes;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.hub.core.HubEvent;
import org.usarsim.wss.hub.core.HubCore;
import org.usarsim.wss.hub.core.RobotSession;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.hub.tcp.Closes;
import org.usarsim.wss.hub.tcp.Descriptors;
import org.usarsim.wss.hub.tcp.PortSelector;
import org.usarsim.wss.hub.tcp.PortSockets;

/**
 * Applies what a step of the core decided: under the hub's lock the step's events are numbered
 * in the {@link Outbox} and its port work resolved to the ports' sockets and given a turn
 * ({@link #taken}); after the lock the socket work is done in the order of the turns, the port
 * memory's timers set, and the events delivered ({@link #apply}). The listening sockets a step
 * stops are handed to the {@link PortSelector}'s thread together and waited for once
 * ({@link Closes}). Holds the sockets of each port the core holds (guarded by the hub's lock):
 * the sockets' side of the hub, apart from the lock and the step ({@link StepExecutor}), which
 * hands it each step's {@link FollowUps}.
 */
final class ChangeApplier {

    /**
     * What follows a step's changes and is a step of its own: the hub's {@link StepExecutor} takes
     * them, and hands itself over with each step it has applied (it is built with this applier,
     * this applier without it).
     */
    interface FollowUps {
        /** A port could not listen again: the core is told. */
        void couldNotListen(Changes.PortAction action, IOException e);

        /** wss.portMemory after a robot left (the timer's call): its ports are forgotten unless it came back. */
        void forgetIfGone(String robot);

        /** Descriptors ran short: remembered ports are given back, out of turn ({@link #takenOutOfTurn}). @return true when some were */
        boolean giveBackRemembered();
    }

    /** A step's changes as they are applied: its port work resolved to sockets, its turn (0: no socket work), what follows. */
    record Applying(Changes changes, List<PortTask> portTasks, long turn, FollowUps followUps) {
    }

    /** A port's socket work with the sockets it is for, resolved under the lock (a port forgotten later keeps its own). */
    record PortTask(Changes.PortAction action, PortSockets sockets) {
    }

    private final Outbox outbox;
    /** The port memory's timer: wss.portMemory after a robot left, its ports are forgotten unless it came back (the rule is the core's). */
    private final ClockTimer forgetTimer;
    private final InetAddress bindAddress;
    private final PortSelector selector;
    private final SocketTurns turns = new SocketTurns();
    private final Map<WssPort, PortSockets> sockets = new HashMap<>();
    /** Ports allocated by the step being taken that do not listen: their sockets, bound listening, stop in its turn. */
    private final List<PortTask> settling = new ArrayList<>();
    /** Ports allocated by the step being taken that listen already: their LISTEN is done. */
    private final Set<WssPort> listenedNow = new HashSet<>();

    ChangeApplier(Outbox outbox, PortSelector selector, InetAddress bindAddress, HubClock clock) {
        this.outbox = outbox;
        this.forgetTimer = new ClockTimer("wss-port-memory", clock);
        this.bindAddress = bindAddress;
        this.selector = selector;
    }

    /**
     * Under the hub's lock, inside the step that opened it, before it is {@link #taken}: the socket
     * of a port the core just allocated, bound by the {@link PortOpener} before the lock
     * ({@link #put}); a port that cannot start accepting does not listen after all.
     */
    void adopt(HubCore core, WssPort port, ServerSocketChannel bound, Changes out) {
        try {
            put(port, PortSockets.adopt(port, bindAddress, selector, bound));
        } catch (IOException e) {
            core.couldNotListen(port, port.epoch(), e.getMessage(), out);
        }
    }

    /**
     * The sockets of a port the core just allocated. A port allocated listening starts accepting
     * at once: its socket only joins the selector (a queue and a wake-up, no I/O on the socket), nothing of
     * an earlier step can concern a port that did not exist, and every later step comes after; so
     * a DNS takes no turn (a mesh forming takes 9,900 in a row). A port allocated not listening
     * stops in the step's turn.
     *
     * @throws IOException when the port cannot start accepting: the core must be told it does not listen
     */
    private void put(WssPort port, PortSockets portSockets) throws IOException {
        sockets.put(port, portSockets);
        if (!port.listening()) {
            settling.add(new PortTask(new Changes.PortAction(Changes.PortWork.STOP, port, port.epoch()), portSockets));
            return;
        }
        listenedNow.add(port);
        portSockets.listen(port.epoch(), null);
    }

    /** Under the hub's lock: the sockets of the ports that have some (a departure's, to drain). */
    List<PortSockets> socketsOf(List<WssPort> ports) {
        return ports.stream().map(sockets::get).filter(Objects::nonNull).toList();
    }

    /** The listening sockets the caller stops, handed to the selector's thread together and waited for once. */
    Closes closes() {
        return selector.closes();
    }

    /**
     * Under the hub's lock: the step's events are numbered in the outbox, its port work resolved
     * and given a turn; {@code followUps} takes what follows it.
     */
    Applying taken(Changes out, FollowUps followUps) {
        List<PortTask> tasks = resolved(out);
        if (tasks.isEmpty() && !out.hasSocketWork()) {
            return new Applying(out, tasks, 0, followUps);
        }
        return new Applying(out, tasks, turns.take(() -> socketWork(out, tasks, followUps)), followUps);
    }

    /**
     * Under the hub's lock, for a step that only gives ports back (descriptors ran short): no turn.
     * A port given back is done with: whatever work of earlier steps is still to come for it does
     * nothing ({@link PortSockets}), so its release need not wait for them, and may be applied from
     * inside another step's turn.
     */
    Applying takenOutOfTurn(Changes out) {
        if (out.portActions().stream().anyMatch(action -> action.work() != Changes.PortWork.RELEASE) || !out.closes().isEmpty()
                || !out.sessionsToClose().isEmpty()) {
            throw new IllegalStateException("only releases are applied out of turn");
        }
        return new Applying(out, resolved(out), 0, null);
    }

    private List<PortTask> resolved(Changes out) {
        if (!out.closes().isEmpty()) {
            outbox.append(List.of(new HubEvent.LinksClosed(List.copyOf(out.closes()))));
        }
        outbox.append(out.events());
        List<PortTask> tasks = new ArrayList<>(settling);
        settling.clear();
        for (Changes.PortAction action : out.portActions()) {
            if (action.work() == Changes.PortWork.LISTEN && listenedNow.contains(action.port())) {
                continue;
            }
            PortSockets portSockets = action.work() == Changes.PortWork.RELEASE ? sockets.remove(action.port())
                    : sockets.get(action.port());
            if (portSockets != null) {
                tasks.add(new PortTask(action, portSockets));
            }
        }
        listenedNow.clear();
        return tasks;
    }

    /**
     * After the lock: the socket work in the order the steps were taken (a break's port stops
     * before the resume that follows it listens again), then the port memory's timers, then the
     * events. Returns once this step's socket work is done: a break has stopped its ports.
     */
    void apply(Applying applying) {
        Changes changes = applying.changes();
        if (applying.turn() > 0) {
            turns.complete(applying.turn());
        }
        FollowUps followUps = applying.followUps();
        changes.forgetLater().forEach(later -> forgetTimer.after(later.afterNs(), () -> followUps.forgetIfGone(later.robot())));
        outbox.deliver();
    }

    /** A step's socket work, in its turn (on whichever thread does the turns then). */
    private void socketWork(Changes changes, List<PortTask> tasks, FollowUps followUps) {
        Closes closes = selector.closes();
        tasks.forEach(task -> portWork(task, closes, followUps));
        closes.await(); // every port this step stopped refuses connections now
        changes.closes().forEach(close -> close.link().close(close.reason()));
        changes.sessionsToClose().forEach(RobotSession::close);
    }

    /**
     * After the lock, from any thread, inside another step's turn too: gives the ports back
     * ({@link #takenOutOfTurn}). The events are delivered unless this thread is in a turn, where
     * a listener's own change would wait for that very turn: the turn's step delivers them.
     */
    void applyOutOfTurn(Applying applying) {
        Closes closes = selector.closes();
        applying.portTasks().forEach(task -> task.sockets().release(closes));
        closes.await();
        if (!turns.heldByCurrentThread()) {
            outbox.deliver();
        }
    }

    /**
     * One port's work. Not a switch on the enum: that compiles to a class of its own, loaded at its
     * first use, and the first stop may come when descriptors have run out (loading a class from a
     * directory of classes takes one).
     */
    private void portWork(PortTask task, Closes closes, FollowUps followUps) {
        Changes.PortWork work = task.action().work();
        if (work == Changes.PortWork.LISTEN) {
            listen(task, closes, followUps); // a port stopped earlier in the step is closed before it listens again (PortSockets)
        } else if (work == Changes.PortWork.STOP) {
            task.sockets().stop(closes);
        } else {
            task.sockets().release(closes);
        }
    }

    /** Out of descriptors, remembered ports of robots that left give theirs back and it is tried once more. */
    private void listen(PortTask task, Closes closes, FollowUps followUps) {
        Changes.PortAction action = task.action();
        try {
            Descriptors.retrying(() -> {
                task.sockets().listen(action.epoch(), closes);
                return null;
            }, followUps::giveBackRemembered);
        } catch (IOException e) {
            followUps.couldNotListen(action, e);
        }
    }

    /** The end: no port memory timer runs any more. */
    void close() {
        forgetTimer.stop();
    }
}
