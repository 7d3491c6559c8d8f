package org.usarsim.wss.monitor;

import java.util.concurrent.TimeUnit;

/**
 * When the publisher compares the state (docs/monitor.md, "Timing"): at most every
 * {@link #STRUCTURE_NS} after the hub said something changed, at least every {@link #COUNTS_NS},
 * and the counts (bytes, rates, positions) told at most every {@link #COUNTS_NS}; and how long it
 * keeps recording the history after the last stream ended ({@link #LINGER_NS}), so that a viewer
 * that reconnects within it resumes. Pure: the time (nanoseconds) is passed in.
 */
final class Cadence {

    static final long STRUCTURE_NS = TimeUnit.MILLISECONDS.toNanos(100);
    static final long COUNTS_NS = TimeUnit.SECONDS.toNanos(1);
    static final long LINGER_NS = TimeUnit.SECONDS.toNanos(60);

    private final long lingerNs;
    private long compared;
    private long counted;
    private long lastStream;
    private boolean started;

    Cadence() {
        this(LINGER_NS);
    }

    /** @param lingerNs how long the history is recorded after the last stream (a benchmark's no-viewer phases set 0) */
    Cadence(long lingerNs) {
        this.lingerNs = lingerNs;
    }

    /** How long to wait from {@code now} before the next comparison, given whether a change waits. */
    long waitNs(long now, boolean changed) {
        if (!started) {
            return 0;
        }
        long next = changed ? compared + STRUCTURE_NS : compared + COUNTS_NS;
        return Math.max(0, next - now);
    }

    /** Whether a comparison is due now. */
    boolean due(long now, boolean changed) {
        return waitNs(now, changed) == 0;
    }

    /** A comparison is made now; returns whether it tells the counts too. */
    boolean compared(long now) {
        boolean counts = !started || now - counted >= COUNTS_NS;
        started = true;
        compared = now;
        if (counts) {
            counted = now;
        }
        return counts;
    }

    /** A stream is open at {@code now}. */
    void streaming(long now) {
        lastStream = now;
    }

    /** Whether the history is recorded: a stream is open, or one was within the linger ({@link #LINGER_NS} unless told). */
    boolean recording(long now, boolean open, boolean everStreamed) {
        return open || everStreamed && now - lastStream < lingerNs;
    }
}
