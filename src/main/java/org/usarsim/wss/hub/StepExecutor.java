package org.usarsim.wss.hub;

import java.net.InetAddress;
import java.nio.channels.ServerSocketChannel;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import java.util.function.LongSupplier;
import java.util.function.ToLongFunction;
import org.usarsim.wss.hub.core.Changes;
import org.usarsim.wss.hub.core.HubCore;
import org.usarsim.wss.hub.core.HubEvent;
import org.usarsim.wss.hub.core.RobotSession;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.hub.tcp.Descriptors;
import org.usarsim.wss.hub.tcp.LinkHub;
import org.usarsim.wss.hub.tcp.PortSelector;
import org.usarsim.wss.hub.tcp.PortSockets;

/**
 * Runs the {@link HubCore} under one lock: each {@link #step} takes the lock once, runs one step of
 * the core with the time now, and applies what it returned after the lock (through the
 * {@link ChangeApplier}: the socket work in the order of the steps, the port memory's timers, the
 * events in order through the {@link Outbox}). Under the lock there is no I/O, no call into the
 * model (a model may call back in from its own thread) and no listener.
 *
 * <p>The time is the one clock the hub was given ({@link System#nanoTime()} in use), read under
 * the lock for each step, so the steps see it move forward in their order.
 */
final class StepExecutor {

    /** One step of the core: changes its state, says in {@code out} what must happen, answers. */
    interface Step<T> {
        T take(HubCore core, long nowNs, Changes out);
    }

    /** A step with no answer. */
    interface Action {
        void take(HubCore core, long nowNs, Changes out);
    }

    /**
     * How many remembered ports of robots that left are given back, at least, each time
     * descriptors run short: room for a few robots' arrivals and connections before the next time.
     */
    private static final int GIVE_BACK_AT_LEAST = 64;

    private final Object lock = new Object();
    private final HubCore core;
    private final LongSupplier clock;
    private final Outbox outbox;
    private final ForgetTimer forgetTimer = new ForgetTimer(this::forgetIfGone);
    private final Descriptors descriptors = new Descriptors(this::giveBackRemembered);
    /** Every listening WSS port, on one thread; it hands what it accepts to the link side. */
    private final PortSelector portSelector;
    private final ChangeApplier applier;

    /** @param linkSide the link side, given this executor: what the port selector hands its connections to */
    StepExecutor(HubCore core, LongSupplier clock, Outbox outbox, InetAddress bindAddress,
            Function<StepExecutor, LinkHub> linkSide) {
        this.core = core;
        this.clock = clock;
        this.outbox = outbox;
        this.portSelector = new PortSelector(linkSide.apply(this));
        this.applier = new ChangeApplier(outbox, forgetTimer, descriptors, portSelector, bindAddress,
                (action, e) -> run((hub, now, out) -> hub.couldNotListen(action.port(), action.epoch(), e.getMessage(), out)));
    }

    Descriptors descriptors() {
        return descriptors;
    }

    PortSelector portSelector() {
        return portSelector;
    }

    long now() {
        return clock.getAsLong();
    }

    /**
     * One step under the lock, its changes applied after it; returns once this step's socket
     * work is done (a break has stopped its ports). Every step wakes a registration that waits
     * for a name: the step may have freed it.
     */
    <T> T step(Step<T> step) {
        Changes out = new Changes();
        T answer;
        ChangeApplier.Applying applying;
        synchronized (lock) {
            answer = step.take(core, clock.getAsLong(), out);
            lock.notifyAll();
            applying = applier.taken(out);
        }
        applier.apply(applying);
        return answer;
    }

    /** As {@link #step}, for a step with no answer. */
    void run(Action action) {
        step((hub, now, out) -> {
            action.take(hub, now, out);
            return null;
        });
    }

    /**
     * As {@link #step}, taken again each time a later step wakes it while its answer says to
     * wait (a name being freed), until {@code patienceNs} of the answer has passed since its first
     * try (0: the answer stands).
     */
    <T> T stepWaiting(Step<T> step, ToLongFunction<T> patienceNs) {
        Changes out = new Changes();
        T answer;
        ChangeApplier.Applying applying;
        synchronized (lock) {
            long start = clock.getAsLong();
            while (true) {
                long now = clock.getAsLong();
                answer = step.take(core, now, out);
                long patience = patienceNs.applyAsLong(answer);
                long left = start + patience - now;
                if (patience == 0 || left <= 0) {
                    break;
                }
                try {
                    TimeUnit.NANOSECONDS.timedWait(lock, left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    break;
                }
            }
            applying = applier.taken(out);
        }
        applier.apply(applying);
        return answer;
    }

    /** A question to the core, or a change of it that makes no {@link Changes}, under the lock. */
    <T> T locked(Function<HubCore, T> call) {
        synchronized (lock) {
            return call.apply(core);
        }
    }

    /**
     * Inside a DNS's step: the new port's socket, bound before the lock; a port that cannot start
     * accepting does not listen after all.
     */
    void adopt(WssPort port, ServerSocketChannel bound, Changes out) {
        applier.adopt(core, port, bound, out);
    }

    /**
     * A robot's control connection closed: it begins to leave (its name stays taken until its
     * ports drained). @return the sockets of its listening ports, to drain; null when the session
     * is not the robot's
     */
    List<PortSockets> beginLeaving(String name, RobotSession session) {
        synchronized (lock) {
            List<WssPort> listening = core.beginLeaving(name, session);
            if (listening == null) {
                return null;
            }
            lock.notifyAll(); // an INIT of the name waits for the drain now
            return listening.stream().map(applier::socketsOf).filter(Objects::nonNull).toList();
        }
    }

    /** An event of no step (the model's own), delivered in order after the steps' events before it. */
    void announce(HubEvent event) {
        synchronized (lock) {
            outbox.append(List.of(event));
        }
        outbox.deliver();
    }

    /** As {@link #announce}, returning once the event is delivered (a link's establishment: its data follows it). */
    void announceDelivered(HubEvent event) {
        long last;
        synchronized (lock) {
            last = outbox.append(List.of(event));
        }
        outbox.deliverThrough(last);
    }

    /**
     * Descriptors ran short: remembered ports of robots that left are given back, the longest gone
     * first, before anyone here is refused. Their sockets are closed at once, even from inside
     * another step's turn (a port given back is done with). @return true when some were
     */
    private boolean giveBackRemembered() {
        Changes out = new Changes();
        ChangeApplier.Applying applying;
        int given;
        synchronized (lock) {
            given = core.giveBackRemembered(GIVE_BACK_AT_LEAST, clock.getAsLong(), out);
            applying = applier.takenOutOfTurn(out);
        }
        applier.applyOutOfTurn(applying);
        return given > 0;
    }

    /** The timer's call, wss.portMemory seconds after a robot left: forget its ports unless it came back. */
    private void forgetIfGone(String name) {
        run((hub, now, out) -> hub.forgetIfGone(name, now, out));
    }

    /** The end: no port memory timer runs any more, and the port selector stops. */
    void close() {
        forgetTimer.close();
        run((hub, now, out) -> hub.close(out));
        portSelector.close();
    }
}
