package org.usarsim.wss.hub;

import java.net.InetAddress;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.HubClock;
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
 * <p>
 * {@link #say} limits every other line of the server's (registered, deregistered, connections
 * established and terminated, WSS ports allocated, pairs changed...; issue 27): they come with
 * a team's normal work, so a kind gets {@link #SAID_FIRST} lines from one address and
 * {@link #SAID_ALL_FIRST} from all in an interval before the rest are counted, and every line is
 * cut at {@link LogLimiter#MAX_MESSAGE} characters as warnings are.
 */
final class WarningLimiter implements AutoCloseable {

    static final int FIRST = LogLimiter.FIRST;
    static final long INTERVAL_NS = LogLimiter.INTERVAL_NS;
    /** Lines of one kind of {@link #say} from one address in an interval: a team's 20 robots on one machine. */
    static final int SAID_FIRST = 20;
    /** Lines of one kind of {@link #say} from all addresses together in an interval. */
    static final int SAID_ALL_FIRST = 100;

    private final LogLimiter limiter;
    private final LogLimiter said;

    /** {@code first} from one address, {@code allFirst} from all, per kind and interval. */
    WarningLimiter(int first, int allFirst, long intervalNs, HubClock clock, LogLimiter.Timer timer) {
        this(first, allFirst, SAID_FIRST, SAID_ALL_FIRST, intervalNs, clock, timer);
    }

    /** As above, with {@code saidFirst} and {@code saidAllFirst} for {@link #say}. */
    WarningLimiter(int first, int allFirst, int saidFirst, int saidAllFirst, long intervalNs, HubClock clock, LogLimiter.Timer timer) {
        this.limiter = new LogLimiter(first, allFirst, intervalNs, clock::nanoTime, timer);
        this.said = new LogLimiter(saidFirst, saidAllFirst, intervalNs, clock::nanoTime, timer);
    }

    /** The server's: {@link #FIRST} a minute on the hub's clock, the summaries written by a {@link #timer}. */
    static WarningLimiter standard(HubClock clock) {
        return new WarningLimiter(FIRST, LogLimiter.ALL_FIRST, INTERVAL_NS, clock, timer(clock));
    }

    /** The server's timer: its one daemon thread, {@code wss-warnings}, lives only while a summary waits (and a second more). */
    static LogLimiter.Timer timer(HubClock clock) {
        return new ClockTimer("wss-warnings", clock);
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

    /**
     * A line of the server's own about what a client did (a robot registered, a connection
     * established), at {@code level}: written, or counted for a summary line of that level
     * ({@code registered robots: 480 more like this from 127.0.0.5 in the last 60 s}).
     *
     * @param source the address of the client it is about; null when none is known
     */
    void say(Logger log, Level level, String kind, InetAddress source, String message) {
        said.log(log, level, kind, source, message, null);
    }

    /** Writes the summary of every interval that has ended. */
    void flush() {
        limiter.flush();
        said.flush();
    }

    /** Writes the summary of every interval, ended or not, and stops the timer. */
    @Override
    public void close() {
        limiter.close();
        said.close();
    }
}
