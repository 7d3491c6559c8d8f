package org.usarsim.wss.hub;

import java.time.Duration;
import java.util.concurrent.TimeUnit;
import org.usarsim.wss.hub.core.HubClock;

/**
 * A hub's clock that a test moves by hand ({@link #advance}): the hub's timers (the port memory,
 * the warnings' summaries), its timed waits (a departure's drain, an INIT waiting for a name) and
 * its log's times follow it, not the machine's time. Its waits last at most a millisecond of the
 * machine's time before they read it again, so a move is seen at once; a timed wait ends only
 * when the test moves the clock past it.
 */
public final class ManualHubClock implements HubClock {

    /** How long a waiter sleeps before it reads the clock again. */
    private static final long POLL_NS = TimeUnit.MILLISECONDS.toNanos(1);

    private volatile long nanos;
    private volatile long millis;

    /** At {@code nanos} on the monotonic clock (anywhere, as {@link System#nanoTime()} may be) and {@code millis} on the wall clock. */
    public ManualHubClock(long nanos, long millis) {
        this.nanos = nanos;
        this.millis = millis;
    }

    /** Near the end of the monotonic clock's range (it may wrap), on 2024-01-02 03:04:05.678 UTC. */
    public ManualHubClock() {
        this(Long.MAX_VALUE - TimeUnit.HOURS.toNanos(1), 1_704_164_645_678L);
    }

    /** Moves both clocks on by {@code by}. */
    public synchronized void advance(Duration by) {
        if (by.isNegative()) {
            throw new IllegalArgumentException("a clock moves on, not back: " + by);
        }
        nanos += by.toNanos();
        millis += by.toMillis();
    }

    /** Moves both clocks on to {@code nanos} (not before the time now). */
    public synchronized void advanceTo(long nanosThen) {
        advance(Duration.ofNanos(nanosThen - nanos));
    }

    @Override
    public long nanoTime() {
        return nanos;
    }

    @Override
    public long wallMillis() {
        return millis;
    }

    @Override
    public long waitNanos(long clockNs) {
        return Math.min(clockNs, POLL_NS);
    }
}
