package org.usarsim.wss.model.simulator;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.usarsim.wss.hub.Wait;

/**
 * A {@link PollClock} that moves only when the test says: the poller sleeps until the test
 * {@link #advance}s the time to its deadline. Every pause the poller asks for is kept, so a test
 * reads the poll interval and the back-off as numbers, not as wall-clock margins.
 */
public final class ManualClock implements PollClock {

    private long now = TimeUnit.HOURS.toNanos(1);
    /** The deadline the poller sleeps until; -1 while it is not sleeping. */
    private long sleepingUntil = -1;
    private final List<Long> pauses = new ArrayList<>();

    @Override
    public synchronized long nanoTime() {
        return now;
    }

    @Override
    public synchronized void sleepUntil(long deadline) throws InterruptedException {
        pauses.add(deadline - now);
        sleepingUntil = deadline;
        notifyAll();
        try {
            while (now < deadline) {
                wait();
            }
        } finally {
            sleepingUntil = -1;
        }
    }

    /** Moves the time on by {@code nanos}. */
    public synchronized void advance(long nanos) {
        now += nanos;
        notifyAll();
    }

    /** The pauses the poller has asked for so far, in nanoseconds, in order. */
    public synchronized List<Long> pauses() {
        return List.copyOf(pauses);
    }

    /**
     * Waits until the poller sleeps, moves the time to its deadline and waits until it sleeps
     * again, its poll (or attempt) done; the time moved, in nanoseconds.
     */
    public long wakePoller() {
        Wait.until("the poller sleeps", this::pollerSleeps);
        long moved;
        int asked;
        synchronized (this) {
            moved = sleepingUntil - now;
            asked = pauses.size();
            advance(moved);
        }
        Wait.until("the poller sleeps again", () -> pollerSleeps() && pauses().size() > asked);
        return moved;
    }

    private synchronized boolean pollerSleeps() {
        return sleepingUntil >= 0 && sleepingUntil > now;
    }
}
