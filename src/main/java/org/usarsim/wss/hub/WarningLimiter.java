package org.usarsim.wss.hub;

import java.net.InetAddress;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Limits the WARNINGs a client can make the server write (a refused connect, an over-long line),
 * so that a client repeating one cannot fill the disk. Per kind of warning and source address,
 * the first {@link #FIRST} in an interval of {@link #INTERVAL_NS} are written; the rest are
 * counted, and when the interval ends one line says how many more there were. The interval of a
 * kind and source starts with its first warning.
 */
final class WarningLimiter implements AutoCloseable {

    static final int FIRST = 5;
    static final long INTERVAL_NS = TimeUnit.SECONDS.toNanos(60);

    /** Runs a task after a delay: a timer thread in the server, by hand in a test. */
    interface Timer {
        void after(long delayNs, Runnable task);

        void stop();
    }

    private record Key(String kind, String source) {
    }

    /** One kind of warning from one source, since {@code start}. */
    private static final class Window {
        final long start;
        final Logger log;
        int written;
        int more;

        Window(long start, Logger log) {
            this.start = start;
            this.log = log;
        }
    }

    static {
        // Loaded now, while a descriptor is free: many of these warnings come when the descriptors
        // have run out, and loading a class from a directory of classes takes one.
        new Window(0, null);
        new Key("", "");
    }

    private final int first;
    private final long intervalNs;
    private final LongSupplier clock;
    private final Timer timer;
    private final Map<Key, Window> windows = new LinkedHashMap<>();

    WarningLimiter(int first, long intervalNs, LongSupplier clock, Timer timer) {
        this.first = first;
        this.intervalNs = intervalNs;
        this.clock = clock;
        this.timer = timer;
    }

    /** The server's: {@link #FIRST} a minute, the summaries written by a {@link #daemonTimer()}. */
    static WarningLimiter standard(LongSupplier clock) {
        return new WarningLimiter(FIRST, INTERVAL_NS, clock, daemonTimer());
    }

    /** A timer whose one daemon thread, {@code wss-warnings}, lives only while a task waits (and a second more). */
    static Timer daemonTimer() {
        ScheduledThreadPoolExecutor executor = new ScheduledThreadPoolExecutor(1, task -> {
            Thread thread = new Thread(task, "wss-warnings");
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
                    // The server has stopped: the summary goes with the next warning, if one comes.
                }
            }

            @Override
            public void stop() {
                executor.shutdownNow();
            }
        };
    }

    void warn(Logger log, String kind, InetAddress source, String message) {
        warn(log, kind, source, message, null);
    }

    /**
     * Writes the warning to {@code log}, or counts it when {@link #FIRST} of this kind from this
     * source were written in the current interval.
     *
     * @param kind what the warnings have in common, named for the summary line ("refused connections")
     */
    void warn(Logger log, String kind, InetAddress source, String message, Throwable thrown) {
        List<Runnable> toWrite = new ArrayList<>();
        boolean write;
        synchronized (this) {
            long now = clock.getAsLong();
            endWindows(now, false, toWrite);
            Key key = new Key(kind, source.getHostAddress());
            Window window = windows.computeIfAbsent(key, k -> new Window(now, log));
            write = window.written < first;
            if (write) {
                window.written++;
            } else if (window.more++ == 0) {
                timer.after(window.start + intervalNs - now, this::flush);
            }
        }
        toWrite.forEach(Runnable::run);
        if (write) {
            log.log(Level.WARNING, message, thrown);
        }
    }

    /** Writes the summary of every interval that has ended. */
    void flush() {
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
                toWrite.add(() -> window.log.warning(line));
            }
        }
    }
}
