package org.usarsim.wss.hub;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import java.util.function.Predicate;
import java.util.function.ToLongFunction;
import org.usarsim.wss.hub.core.Changes;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.hub.core.HubCore;
import org.usarsim.wss.hub.core.HubEvent;

/**
 * Runs the {@link HubCore} under one lock: each {@link #step} takes the lock once, runs one step of
 * the core with the time now, and applies what it returned after the lock (through the
 * {@link ChangeApplier}: the socket work in the order of the steps, the port memory's timers, the
 * events in order through the {@link Outbox}). Under the lock there is no I/O, no call into the
 * model (a model may call back in from its own thread) and no listener. It holds no socket: the
 * applier holds them, and is handed this executor with each step for what follows it
 * ({@link ChangeApplier.FollowUps}: each is a step too).
 *
 * <p>The time is the hub's one {@link HubClock}, read under the lock for each step, so the steps
 * see it move forward in their order.
 */
final class StepExecutor implements ChangeApplier.FollowUps {

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
    private final HubClock clock;
    private final Outbox outbox;
    private final ChangeApplier applier;

    StepExecutor(HubCore core, HubClock clock, Outbox outbox, ChangeApplier applier) {
        this.core = core;
        this.clock = clock;
        this.outbox = outbox;
        this.applier = applier;
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
            answer = step.take(core, clock.nanoTime(), out);
            lock.notifyAll();
            applying = applier.taken(out, this);
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
            long start = clock.nanoTime();
            while (true) {
                long now = clock.nanoTime();
                answer = step.take(core, now, out);
                long patience = patienceNs.applyAsLong(answer);
                long left = start + patience - now;
                if (patience == 0 || left <= 0) {
                    break;
                }
                try {
                    TimeUnit.NANOSECONDS.timedWait(lock, clock.waitNanos(left));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    break;
                }
            }
            applying = applier.taken(out, this);
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

    /** An event of no step (the model's own), delivered in order after the steps' events before it. */
    void announce(HubEvent event) {
        synchronized (lock) {
            outbox.append(List.of(event));
        }
        outbox.deliver();
    }

    /**
     * As {@link #announce}, if the core says {@code still} under the lock (a link's establishment:
     * not once a step closed it), returning once the event is delivered (its data follows it).
     *
     * @return whether it was announced
     */
    boolean announceDeliveredIf(Predicate<HubCore> still, HubEvent event) {
        long last;
        synchronized (lock) {
            if (!still.test(core)) {
                return false;
            }
            last = outbox.append(List.of(event));
        }
        outbox.deliverThrough(last);
        return true;
    }

    @Override
    public void couldNotListen(Changes.PortAction action, IOException e) {
        run((hub, now, out) -> hub.couldNotListen(action.port(), action.epoch(), e.getMessage(), out));
    }

    /** The port memory's timer, wss.portMemory seconds after a robot left: forget its ports unless it came back. */
    @Override
    public void forgetIfGone(String robot) {
        run((hub, now, out) -> hub.forgetIfGone(robot, now, out));
    }

    /**
     * Descriptors ran short ({@link org.usarsim.wss.hub.tcp.Descriptors}): remembered ports of
     * robots that left are given back, the longest gone first, before anyone here is refused.
     * Their sockets are closed at once, even from inside another step's turn (a port given back is
     * done with). @return true when some were
     */
    @Override
    public boolean giveBackRemembered() {
        Changes out = new Changes();
        ChangeApplier.Applying applying;
        int given;
        synchronized (lock) {
            given = core.giveBackRemembered(GIVE_BACK_AT_LEAST, clock.nanoTime(), out);
            applying = applier.takenOutOfTurn(out);
        }
        applier.applyOutOfTurn(applying);
        return given > 0;
    }

    /**
     * The end: the core closes, every port stops and every link closes; returns once every event
     * so far is delivered (the robots deregistered, the connections terminated), even those another
     * thread was delivering, so that the hub's last line comes after them.
     */
    void close() {
        run((hub, now, out) -> hub.close(out));
        long last;
        synchronized (lock) {
            last = outbox.append(List.of());
        }
        outbox.deliverThrough(last);
    }
}
