package org.usarsim.wss.gui;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.SimpleFormatter;
import org.usarsim.wss.LogText;

/**
 * The server's log lines for the window, as the original wrote them: {@code debug: } for INFO and
 * below, {@code WARNING: } for WARNING and SEVERE. {@link #publish} (any thread) only queues the
 * line; the window takes them in batches on its event thread. At most {@link #MAX_QUEUED} lines
 * wait: when the window falls behind, the oldest are dropped and counted, never the server slowed.
 * Control characters are escaped as in the headless log ({@link LogText}); the JDK's own records
 * are left out.
 */
public final class WindowLog extends Handler {

    static final int MAX_QUEUED = 5000;
    /** The loggers of the JDK's own classes, by their names' beginnings. */
    private static final List<String> JDK_LOGGERS = List.of("java.", "javax.", "sun.", "jdk.", "com.sun.");

    private final ArrayDeque<String> queue = new ArrayDeque<>();
    private long dropped;

    public WindowLog() {
        setFormatter(new SimpleFormatter());
        setLevel(Level.ALL);
    }

    /** The line as the window shows it. */
    static String line(Level level, String message) {
        return (level.intValue() >= Level.WARNING.intValue() ? "WARNING: " : "debug: ") + message;
    }

    /**
     * The server's records, not the JDK's own ({@code java.util.prefs} says "Created user preferences
     * directory." the first time the window stores its settings): those go to standard output only.
     */
    @Override
    public boolean isLoggable(LogRecord record) {
        String logger = record == null ? null : record.getLoggerName();
        if (logger != null && JDK_LOGGERS.stream().anyMatch(logger::startsWith)) {
            return false;
        }
        return super.isLoggable(record);
    }

    @Override
    public void publish(LogRecord record) {
        if (record == null || !isLoggable(record)) {
            return;
        }
        String message = getFormatter().formatMessage(record);
        if (record.getThrown() != null) {
            message += " (" + record.getThrown() + ")";
        }
        String text = line(record.getLevel(), LogText.escape(message));
        synchronized (queue) {
            if (queue.size() == MAX_QUEUED) {
                queue.removeFirst();
                dropped++;
            }
            queue.addLast(text);
        }
    }

    /** The lines queued since the last call, oldest first; a note first when some were dropped. */
    List<String> drain() {
        synchronized (queue) {
            List<String> lines = new ArrayList<>(queue.size() + 1);
            if (dropped > 0) {
                lines.add(line(Level.WARNING, dropped + " log lines were dropped: they came faster than the window shows them"));
                dropped = 0;
            }
            lines.addAll(queue);
            queue.clear();
            return lines;
        }
    }

    @Override
    public void flush() {
    }

    @Override
    public void close() {
    }
}
