package org.usarsim.wss;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

/** What a logger (and the loggers under it) writes while a test runs; {@link #close()} detaches it and restores the level. */
public final class LogCapture implements AutoCloseable {

    /** Every record, in order; safe to read while the code under test logs. */
    public final List<LogRecord> records = new CopyOnWriteArrayList<>();

    private final Logger logger;
    private final Level levelBefore;
    private final Handler handler = new Handler() {
        @Override
        public void publish(LogRecord record) {
            records.add(record);
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    };

    private LogCapture(Logger logger, Level level) {
        this.logger = logger;
        levelBefore = logger.getLevel();
        if (level != null) {
            logger.setLevel(level);
        }
        logger.addHandler(handler);
    }

    /** Captures what the named logger writes, at {@code level} and above (null: its level as it is). */
    public static LogCapture of(String loggerName, Level level) {
        return new LogCapture(Logger.getLogger(loggerName), level);
    }

    /** How many records at this level contain {@code part}. */
    public long count(Level level, String part) {
        return records.stream().filter(r -> r.getLevel().equals(level) && r.getMessage().contains(part)).count();
    }

    /** The messages at this level, in order. */
    public List<String> messages(Level level) {
        return records.stream().filter(r -> r.getLevel().equals(level)).map(LogRecord::getMessage).toList();
    }

    @Override
    public void close() {
        logger.removeHandler(handler);
        logger.setLevel(levelBefore);
    }

    @Override
    public String toString() {
        return records.stream().map(r -> r.getLevel() + " " + r.getMessage()).toList().toString();
    }
}
