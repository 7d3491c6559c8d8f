package org.usarsim.wss;

import java.util.concurrent.TimeUnit;

/**
 * The one way a model's thread of its own is stopped (the simulator models' poller, the replay's
 * player): tell it to stop, then wait for it to end, at most {@link #WAIT_SECONDS}. A thread that
 * does not end by then is left to end by itself (it is a daemon); an interrupt of the caller ends
 * the wait and stays set.
 */
public final class ThreadStop {

    /** How long a stop waits for the thread to end. */
    public static final long WAIT_SECONDS = 5;

    private ThreadStop() {
    }

    /**
     * Runs {@code signal}, which tells the thread to stop (sets its flag, wakes or interrupts it,
     * closes what it blocks on), then waits for {@code thread} to end.
     *
     * @return whether the thread ended within the wait
     */
    public static boolean stop(Thread thread, Runnable signal) {
        signal.run();
        try {
            thread.join(TimeUnit.SECONDS.toMillis(WAIT_SECONDS));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return !thread.isAlive();
    }
}
