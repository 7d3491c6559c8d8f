package org.usarsim.wss.hub;

import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * How long the WSS ports of a robot that left keep their numbers ({@code wss.portMemory}): when
 * each robot left, and one thread that tells the hub, that long after a departure, to forget
 * the robot's ports. Guarded by the hub's lock, except {@link #close}.
 */
final class PortMemory {

    /** Never forget. */
    static final int FOREVER = -1;

    private final long memoryNs;
    private final boolean forever;
    /** When each robot that left and still has ports left (System.nanoTime()). */
    private final Map<String, Long> goneSince = new HashMap<>();
    /** Runs the forgetting; none when ports are forgotten at once or never. */
    private final ScheduledThreadPoolExecutor timer;
    private final Consumer<String> forget;

    /** @param forget called with a robot's name, without the hub's lock, once it may have been gone long enough */
    PortMemory(int seconds, Consumer<String> forget) {
        this.forever = seconds == FOREVER;
        this.memoryNs = TimeUnit.SECONDS.toNanos(Math.max(0, seconds));
        this.forget = forget;
        if (seconds > 0) {
            timer = new ScheduledThreadPoolExecutor(1, task -> {
                Thread thread = new Thread(task, "wss-port-memory");
                thread.setDaemon(true);
                return thread;
            });
            timer.setRemoveOnCancelPolicy(true);
            timer.prestartAllCoreThreads(); // the one thread is there from the start, not after the first departure
        } else {
            timer = null;
        }
    }

    /** A robot left. @return true when its ports are to be forgotten now (wss.portMemory = 0) */
    boolean left(String robot) {
        if (forever) {
            return false;
        }
        goneSince.put(robot, System.nanoTime());
        if (timer == null) {
            return true;
        }
        timer.schedule(() -> forget.accept(robot), memoryNs, TimeUnit.NANOSECONDS);
        return false;
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

    void close() {
        if (timer != null) {
            timer.shutdownNow();
        }
    }
}
