package org.usarsim.wss.monitor;

import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.SimpleFormatter;
import org.usarsim.wss.LogText;

/**
 * The server's log records as {@code log} events (docs/monitor.md): each at its level, its message
 * formatted and escaped as the headless log and the window write it ({@link LogText}), a throwable
 * named after it. The JDK's own records are left out, as the window leaves them out. Only offers to
 * the publisher's queue: a log line never waits for a viewer.
 */
final class LogEvents extends Handler {

    private static final List<String> JDK_LOGGERS = List.of("java.", "javax.", "sun.", "jdk.", "com.sun.");
    private final Publisher publisher;

    LogEvents(Publisher publisher) {
        this.publisher = publisher;
        setFormatter(new SimpleFormatter());
        setLevel(Level.ALL);
    }

    @Override
    public void publish(LogRecord record) {
        if (record == null || !isLoggable(record)) {
            return;
        }
        String logger = record.getLoggerName();
        if (logger != null && JDK_LOGGERS.stream().anyMatch(logger::startsWith)) {
            return;
        }
        String message = getFormatter().formatMessage(record);
        if (record.getThrown() != null) {
            message += " (" + record.getThrown() + ")";
        }
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("time", Instant.ofEpochMilli(record.getMillis()).toString());
        json.put("level", record.getLevel().getName());
        json.put("logger", logger);
        json.put("message", LogText.escape(message));
        publisher.log(json);
    }

    @Override
    public void flush() {
    }

    @Override
    public void close() {
    }
}
