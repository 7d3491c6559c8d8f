package org.usarsim.wss.hub;

import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * How long the WSS ports of a robot that left keep their numbers ({@code wss.portMemory}): when
 * each robot left, and one thread that tells the hub, that long after a departure, to forget
 * the robot's ports. The thread is started at the first departure, not before, so a hub whose
 * start fails (its control port in use, say) leaves no thread. Guarded by the hub's lock, except
 * the timer, which {@link #close} (without that lock) also touches: that is guarded by this object.
 */
final class PortMemory {

    /** Never forget. */
    static final int FOREVER = -1;

    private final long memoryNs;
    private final boolean forever;
    /** When each robot that left and still has ports left (System.nanoTime()). */
    private final Map<String, Long> goneSince = new HashMap<>();
    /** Whether ports are forgotten after a while, so a timer is needed (not at once, not never). */
    private final boolean timed;
    /** Runs the forgetting; started at the first departure (guarded by this object). */
    private ScheduledThreadPoolExecutor timer;
    private boolean closed;
    private final Consumer<String> forget;

    /** @param forget called with a robot's name, without the hub's lock, once it may have been gone long enough */
    PortMemory(int seconds, Consumer<String> forget) {
        this.forever = seconds == FOREVER;
        this.memoryNs = TimeUnit.SECONDS.toNanos(Math.max(0, seconds));
        this.forget = forget;
        this.timed = seconds > 0;
    }

    /** A robot left. @return true when its ports are to be forgotten now (wss.portMemory = 0) */
    boolean left(String robot) {
        if (forever) {
            return false;
        }
        goneSince.put(robot, System.nanoTime());
        if (!timed) {
            return true;
        }
        schedule(() -> forget.accept(robot));
        return false;
    }

    private synchronized void schedule(Runnable task) {
        if (closed) {
            return;
        }
        if (timer == null) {
            timer = new ScheduledThreadPoolExecutor(1, runnable -> {
                Thread thread = new Thread(runnable, "wss-port-memory");
                thread.setDaemon(true);
                return thread;
            });
            timer.setRemoveOnCancelPolicy(true);
        }
        timer.schedule(task, memoryNs, TimeUnit.NANOSECONDS);
    }

    /** A robot registered again, or its ports were all forgotten: nothing to remember about its departure. */
    void clear(String robot) {
        goneSince.remove(robot);
    }

    /** Whether the robot has been gone at least as long as ports are remembered. */
    boolean expired(String robot) {
        Long since = goneSince.get(robot);
        return since != null && System.nanoTime() - since >= memoryNs;
    }

    /** Whole seconds since the robot left (0 when it has not). */
    long goneSeconds(String robot) {
        Long since = goneSince.get(robot);
        return since == null ? 0 : TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - since);
    }

    synchronized void close() {
        closed = true;
        if (timer != null) {
            timer.shutdownNow();
        }
    }
}
