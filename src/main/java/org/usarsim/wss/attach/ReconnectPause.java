package org.usarsim.wss.attach;

/**
 * How long an attached window waits before it connects again: {@link #FIRST_MS} after the first
 * loss, doubled at each loss in a row up to {@link #MAX_MS}, back to the first once a connection
 * worked. Pure: the time (ms, any origin) is passed in.
 */
final class ReconnectPause {

    static final long FIRST_MS = 500;
    static final long MAX_MS = 10_000;

    private long pauseMs;
    private long retryAtMs;

    /** The connection was lost (or could not be made) at {@code nowMs}: when to try again. */
    long lost(long nowMs) {
        pauseMs = pauseMs == 0 ? FIRST_MS : Math.min(MAX_MS, pauseMs * 2);
        retryAtMs = nowMs + pauseMs;
        return retryAtMs;
    }

    /** A connection worked: the next loss waits the first pause again. */
    void connected() {
        pauseMs = 0;
    }

    /** The pause of the last loss (0: connected since). */
    long pauseMs() {
        return pauseMs;
    }

    /** Whole seconds until the retry, rounded up (0 once it is due), as the window's banner says it. */
    long secondsLeft(long nowMs) {
        long left = Math.max(0, retryAtMs - nowMs);
        return (left + 999) / 1000;
    }
}
