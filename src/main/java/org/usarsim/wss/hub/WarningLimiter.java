package org.usarsim.wss.hub;

import java.net.InetAddress;
import java.util.function.LongSupplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.net.LogLimiter;

/**
 * Limits the WARNINGs a client can make the server write (a refused connect, an over-long line),
 * so that a client repeating one, or a crowd of clients, cannot fill the disk: the hub's
 * {@link LogLimiter}. Per kind of warning, the first {@link #FIRST} from one source address and
 * the first {@link LogLimiter#ALL_FIRST} from all of them in an interval of {@link #INTERVAL_NS}
 * are written; the rest are counted, and when the interval ends one line says how many more
 * there were. The interval of a kind and source starts with its first warning.
 * <p>
 * {@link #info} is the same limit for the INFO lines a client causes (an operator's FORCE, with
 * the names it was given), kinds of their own.
 */
final class WarningLimiter implements AutoCloseable {

    static final int FIRST = LogLimiter.FIRST;
    static final long INTERVAL_NS = LogLimiter.INTERVAL_NS;

    /** Runs a task after a delay: a timer thread in the server, by hand in a test. */
    interface Timer extends LogLimiter.Timer {
    }

    private final LogLimiter limiter;

    /** {@code first} from one address, {@code allFirst} from all, per kind and interval. */
    WarningLimiter(int first, int allFirst, long intervalNs, LongSupplier clock, Timer timer) {
        this.limiter = new LogLimiter(first, allFirst, intervalNs, clock, timer);
    }

    /** The server's: {@link #FIRST} a minute, the summaries written by a {@link #daemonTimer()}. */
    static WarningLimiter standard(LongSupplier clock) {
        return new WarningLimiter(FIRST, LogLimiter.ALL_FIRST, INTERVAL_NS, clock, daemonTimer());
    }

    /** A timer whose one daemon thread, {@code wss-warnings}, lives only while a task waits (and a second more). */
    static Timer daemonTimer() {
        LogLimiter.Timer timer = LogLimiter.daemonTimer("wss-warnings");
        return new Timer() {
            @Override
            public void after(long delayNs, Runnable task) {
                timer.after(delayNs, task);
            }

            @Override
            public void stop() {
                timer.stop();
            }
        };
    }

    void warn(Logger log, String kind, InetAddress source, String message) {
        warn(log, kind, source, message, null);
    }

    /**
     * Writes the warning to {@code log}, or counts it when this kind's limit from this source, or
     * from all sources, is reached in the current interval.
     *
     * @param kind what the warnings have in common, named for the summary line ("refused connections")
     */
    void warn(Logger log, String kind, InetAddress source, String message, Throwable thrown) {
        limiter.log(log, Level.WARNING, kind, source, message, thrown);
    }

    /**
     * An INFO line a client causes, limited as the warnings are: written, or counted for an INFO
     * summary ({@code operator commands: 995 more like this from 127.0.0.1 in the last 60 s}).
     * Its kinds are its own; do not share one with {@link #warn}.
     */
    void info(Logger log, String kind, InetAddress source, String message) {
        limiter.log(log, Level.INFO, kind, source, message, null);
    }

    /**
     * An INFO line with no address to blame (a listener of the hub's events, which carry none):
     * only the kind's total applies, {@link LogLimiter#ALL_FIRST} an interval, then an INFO summary
     * {@code forced pairs: 980 more like this from any address in the last 60 s}.
     */
    void info(Logger log, String kind, String message) {
        limiter.log(log, Level.INFO, kind, null, message, null);
    }

    /** Writes the summary of every interval that has ended. */
    void flush() {
        limiter.flush();
    }

    /** Writes the summary of every interval, ended or not, and stops the timer. */
    @Override
    public void close() {
        limiter.close();
    }
}
