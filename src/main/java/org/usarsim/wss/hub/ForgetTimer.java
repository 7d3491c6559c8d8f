package org.usarsim.wss.hub;

import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * The port memory's timer: asks the hub, wss.portMemory after a robot left, to forget the robot's
 * ports unless it came back (the rule is the core's). Its thread is started at the first
 * departure, not before, so a hub whose start fails leaves no thread.
 */
final class ForgetTimer {

    private final Consumer<String> forget;
    private ScheduledThreadPoolExecutor timer;
    private boolean closed;

    /** @param forget called with a robot's name, without the hub's lock, once it may have been gone long enough */
    ForgetTimer(Consumer<String> forget) {
        this.forget = forget;
    }

    synchronized void schedule(String robot, long afterNs) {
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
        timer.schedule(() -> forget.accept(robot), afterNs, TimeUnit.NANOSECONDS);
    }

    synchronized void close() {
        closed = true;
        if (timer != null) {
            timer.shutdownNow();
        }
    }
}
