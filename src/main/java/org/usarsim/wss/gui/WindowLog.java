package org.usarsim.wss.gui;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.SimpleFormatter;

/**
 * The server's log lines for the window, as the original wrote them: {@code debug: } for INFO and
 * below, {@code WARNING: } for WARNING and SEVERE. {@link #publish} (any thread) only queues the
 * line; the window takes them in batches on its event thread. At most {@link #MAX_QUEUED} lines
 * wait: when the window falls behind, the oldest are dropped and counted, never the server slowed.
 */
public final class WindowLog extends Handler {

    static final int MAX_QUEUED = 5000;

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

    @Override
    public void publish(LogRecord record) {
        if (record == null || !isLoggable(record)) {
            return;
        }
        String message = getFormatter().formatMessage(record);
        if (record.getThrown() != null) {
            message += " (" + record.getThrown() + ")";
        }
        String text = line(record.getLevel(), message);
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
