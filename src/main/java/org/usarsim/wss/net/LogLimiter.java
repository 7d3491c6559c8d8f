package org.usarsim.wss.net;

import java.net.InetAddress;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Limits the log lines clients can make a server write, so that no client, and no crowd of
 * clients, can fill the disk or drown the log (docs/reliability.md, "Floods and warnings"). The
 * hub's warnings go through it ({@code hub.WarningLimiter}), and the world server's lines.
 * <p>
 * Per kind of line, in an interval of {@link #INTERVAL_NS} that starts with the kind's first line:
 * at most {@link #FIRST} from one source address, and at most {@link #ALL_FIRST} from all addresses
 * together (5,000 addresses, or the endless addresses of IPv6, would each have their own five).
 * The rest are counted, and when an interval ends one line says how many more there were, at the
 * level of the lines it stands for: {@code refused connections: 35 more like this from 127.0.0.3
 * in the last 60 s} for one address, {@code ... from any address ...} for the total. A message
 * longer than {@link #MAX_MESSAGE} characters (a name of 32 KB) is cut, saying how much was left out.
 * <p>
 * The summaries are written by a {@link Timer}, or before the next line if that comes first, and
 * all at once by {@link #close}. Nothing is written under the limiter's lock.
 */
public final class LogLimiter implements AutoCloseable {

    /** Lines of one kind from one address in an interval. */
    public static final int FIRST = 5;
    /** Lines of one kind from all addresses together in an interval. */
    public static final int ALL_FIRST = 20;
    public static final long INTERVAL_NS = TimeUnit.SECONDS.toNanos(60);
    /** The longest message written whole; longer ones are cut. */
    public static final int MAX_MESSAGE = 1000;

    /** Runs a task after a delay: a timer thread in a server, by hand in a test. */
    public interface Timer {
        void after(long delayNs, Runnable task);

        void stop();
    }

    /** A kind of line from one source ({@link #ANY}: the kind's total). */
    private record Key(String kind, String source) {
    }

    private static final String ANY = "any address";

    /** One kind of line from one source (or all), since {@code start}. */
    private static final class Window {
        final long start;
        final Logger log;
        final Level level;
        int written;
        int more;

        Window(long start, Logger log, Level level) {
            this.start = start;
            this.log = log;
            this.level = level;
        }
    }

    static {
        // Loaded now, while a descriptor is free: many of these lines come when the descriptors have
        // run out, and loading a class from a directory of classes takes one.
        new Window(0, null, null);
        new Key("", "");
        cut("");
    }

    private final int first;
    private final int allFirst;
    private final long intervalNs;
    private final LongSupplier clock;
    private final Timer timer;
    /**
     * The open intervals. Bounded: a source's own window is opened only when one of its lines is
     * written, at most {@link #allFirst} per kind and interval.
     */
    private final Map<Key, Window> windows = new LinkedHashMap<>();

    public LogLimiter(int first, int allFirst, long intervalNs, LongSupplier clock, Timer timer) {
        this.first = first;
        this.allFirst = allFirst;
        this.intervalNs = intervalNs;
        this.clock = clock;
        this.timer = timer;
    }

    /** A server's: {@link #FIRST} and {@link #ALL_FIRST} a minute, the summaries written by a {@link #daemonTimer}. */
    public static LogLimiter standard(String threadName) {
        return new LogLimiter(FIRST, ALL_FIRST, INTERVAL_NS, System::nanoTime, daemonTimer(threadName));
    }

    /** A timer whose one daemon thread, named so, lives only while a task waits (and a second more). */
    public static Timer daemonTimer(String threadName) {
        ScheduledThreadPoolExecutor executor = new ScheduledThreadPoolExecutor(1, task -> {
            Thread thread = new Thread(task, threadName);
            thread.setDaemon(true);
            return thread;
        });
        executor.setKeepAliveTime(1, TimeUnit.SECONDS);
        executor.allowCoreThreadTimeOut(true);
        return new Timer() {
            @Override
            public void after(long delayNs, Runnable task) {
                try {
                    executor.schedule(task, delayNs, TimeUnit.NANOSECONDS);
                } catch (RejectedExecutionException stopped) {
                    // The server has stopped: the summary goes with the next line, if one comes.
                }
            }

            @Override
            public void stop() {
                executor.shutdownNow();
            }
        };
    }

    /**
     * Writes the line to {@code log} at {@code level}, or counts it when this kind's limit from this
     * source, or from all sources, is reached in the current interval.
     *
     * @param kind what the lines have in common, named for the summary line ("refused connections");
     *        a kind has one level
     * @param source the address that caused it; null when none is known (then only the kind's total applies)
     * @param thrown written with the line; null for none
     */
    public void log(Logger log, Level level, String kind, InetAddress source, String message, Throwable thrown) {
        List<Runnable> toWrite = new ArrayList<>();
        boolean write;
        synchronized (this) {
            long now = clock.getAsLong();
            endWindows(now, false, toWrite);
            Key allKey = new Key(kind, ANY);
            Window all = windows.get(allKey);
            if (all == null) {
                all = new Window(now, log, level);
                windows.put(allKey, all);
            }
            Key ownKey = source == null ? null : new Key(kind, source.getHostAddress());
            Window own = ownKey == null ? null : windows.get(ownKey);
            if (own != null && own.written >= first) {
                count(own, now);
                write = false;
            } else if (all.written >= allFirst) {
                count(all, now);
                write = false;
            } else {
                if (own == null && ownKey != null) {
                    own = new Window(now, log, level);
                    windows.put(ownKey, own);
                }
                if (own != null) {
                    own.written++;
                }
                all.written++;
                write = true;
            }
        }
        toWrite.forEach(Runnable::run);
        if (write) {
            log.log(level, cut(message), thrown);
        }
    }

    /** Under the lock: one more line not written; the first asks the timer for the summary. */
    private void count(Window window, long now) {
        if (window.more++ == 0) {
            timer.after(window.start + intervalNs - now, this::flush);
        }
    }

    /** The message, or its first {@link #MAX_MESSAGE} characters and how many more there were. */
    static String cut(String message) {
        if (message == null || message.length() <= MAX_MESSAGE) {
            return message;
        }
        int end = Character.isHighSurrogate(message.charAt(MAX_MESSAGE - 1)) ? MAX_MESSAGE - 1 : MAX_MESSAGE;
        return message.substring(0, end) + "... (" + (message.length() - end) + " more characters)";
    }

    /** Writes the summary of every interval that has ended. */
    public void flush() {
        end(false);
    }

    /** Writes the summary of every interval, ended or not, and stops the timer. */
    @Override
    public void close() {
        timer.stop();
        end(true);
    }

    private void end(boolean all) {
        List<Runnable> toWrite = new ArrayList<>();
        synchronized (this) {
            endWindows(clock.getAsLong(), all, toWrite);
        }
        toWrite.forEach(Runnable::run);
    }

    /** Under the lock: forgets the windows that have ended (all of them when {@code all}), adding their summaries. */
    private void endWindows(long now, boolean all, List<Runnable> toWrite) {
        List<Runnable> totals = new ArrayList<>();
        for (Iterator<Map.Entry<Key, Window>> it = windows.entrySet().iterator(); it.hasNext(); ) {
            Map.Entry<Key, Window> entry = it.next();
            Window window = entry.getValue();
            long elapsed = now - window.start;
            if (!all && elapsed < intervalNs) {
                continue;
            }
            it.remove();
            if (window.more > 0) {
                long seconds = Math.max(1, TimeUnit.NANOSECONDS.toSeconds(Math.min(elapsed, intervalNs) + 999_999_999L));
                String line = entry.getKey().kind() + ": " + window.more + " more like this from " + entry.getKey().source()
                        + " in the last " + seconds + " s";
                // An address's summary before its kind's total.
                (entry.getKey().source().equals(ANY) ? totals : toWrite).add(() -> window.log.log(window.level, line));
            }
        }
        toWrite.addAll(totals);
    }
}
