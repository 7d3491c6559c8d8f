package org.usarsim.wss.model.simulator;

import java.util.concurrent.TimeUnit;

/**
 * Where the poller takes its time from and how it waits: {@link #SYSTEM} for real; a test gives a
 * clock it moves itself, so that the poll interval, the back-off and the hold time run without
 * waiting for them.
 */
public interface PollClock {

    /** The time in nanoseconds, as {@link System#nanoTime()}: only differences mean anything. */
    long nanoTime();

    /** Returns once {@link #nanoTime()} has reached {@code deadline} (or a little before: the caller checks). */
    void sleepUntil(long deadline) throws InterruptedException;

    /** The machine's clock. */
    PollClock SYSTEM = new PollClock() {
        @Override
        public long nanoTime() {
            return System.nanoTime();
        }

        @Override
        public void sleepUntil(long deadline) throws InterruptedException {
            TimeUnit.NANOSECONDS.sleep(deadline - System.nanoTime());
        }
    };
}
