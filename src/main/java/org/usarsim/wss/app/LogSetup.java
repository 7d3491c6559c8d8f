package org.usarsim.wss.app;

import java.io.PrintStream;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.logging.Formatter;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import java.util.logging.StreamHandler;
import org.usarsim.wss.LogText;

/** Sends the server's log to standard output (Main.run's {@code out}), one line per event, each with a timestamp. */
final class LogSetup {

    /** How a line's time is written (by {@link OneLine#time}: this to the second, then the milliseconds). */
    static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss.SSS");
    private static final DateTimeFormatter SECOND = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss");

    private LogSetup() {
    }

    /**
     * One line: time, level, message, and the exception's message if there is one; control
     * characters escaped ({@link LogText}).
     */
    static final class OneLine extends Formatter {
        /** The second (and the zone) formatted last, and its text up to the milliseconds. */
        private long second = Long.MIN_VALUE;
        private ZoneId zone;
        private String secondText;

        @Override
        public String format(LogRecord record) {
            StringBuilder line = new StringBuilder(128);
            time(record.getInstant(), line);
            line.append(' ').append(record.getLevel().getName()).append(' ')
                    .append(LogText.escape(formatMessage(record)));
            Throwable thrown = record.getThrown();
            if (thrown != null) {
                // Still one line: the exception and where it was thrown.
                StringBuilder about = new StringBuilder(" (").append(thrown);
                if (thrown.getStackTrace().length > 0) {
                    about.append(" at ").append(thrown.getStackTrace()[0]);
                }
                line.append(LogText.escape(about.append(')').toString().replace('\n', ' ')));
            }
            return line.append(System.lineSeparator()).toString();
        }

        /**
         * The time as {@link #TIME} writes it. The date and time to the second are formatted once
         * a second: a mesh forming writes thousands of lines a second (a WSS port allocated per
         * DNS), and the formatter was a tenth of the server's work for each.
         */
        private synchronized void time(Instant instant, StringBuilder line) {
            ZoneId now = ZoneId.systemDefault();
            if (instant.getEpochSecond() != second || !now.equals(zone)) {
                second = instant.getEpochSecond();
                zone = now;
                secondText = SECOND.format(LocalDateTime.ofInstant(Instant.ofEpochSecond(second), now));
            }
            int millis = instant.getNano() / 1_000_000;
            line.append(secondText).append('.').append((char) ('0' + millis / 100)).append((char) ('0' + millis / 10 % 10))
                    .append((char) ('0' + millis % 10));
        }
    }

    /**
     * The root logger's handlers and level as they are now; {@link Saved#restore()} puts them back
     * (Main.run does when it returns, so a run inside another program leaves its logging as it was).
     */
    static Saved save() {
        Logger root = Logger.getLogger("");
        return new Saved(List.of(root.getHandlers()), root.getLevel());
    }

    /** The root logger's handlers and level at {@link #save()}. */
    static final class Saved {
        private final List<Handler> handlers;
        private final Level level;

        private Saved(List<Handler> handlers, Level level) {
            this.handlers = handlers;
            this.level = level;
        }

        /** Flushes the handlers added since (not closed: their streams belong to the caller) and puts back the saved ones. */
        void restore() {
            Logger root = Logger.getLogger("");
            for (Handler handler : root.getHandlers()) {
                if (!handlers.contains(handler)) {
                    handler.flush();
                    root.removeHandler(handler);
                }
            }
            List<Handler> now = List.of(root.getHandlers());
            handlers.stream().filter(handler -> !now.contains(handler)).forEach(root::addHandler);
            root.setLevel(level);
        }
    }

    static void install(PrintStream out, Level level) {
        Logger root = Logger.getLogger("");
        for (Handler handler : root.getHandlers()) {
            root.removeHandler(handler);
        }
        Handler handler = new StreamHandler(out, new OneLine()) {
            @Override
            public synchronized void publish(LogRecord record) {
                super.publish(record);
                flush();
            }
        };
        handler.setLevel(Level.ALL);
        root.addHandler(handler);
        root.setLevel(level);
    }
}
