package org.usarsim.wss.app;

import java.io.PrintStream;
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

    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss.SSS");

    private LogSetup() {
    }

    /**
     * One line: time, level, message, and the exception's message if there is one; control
     * characters escaped ({@link LogText}).
     */
    static final class OneLine extends Formatter {
        @Override
        public String format(LogRecord record) {
            StringBuilder line = new StringBuilder(128)
                    .append(TIME.format(LocalDateTime.ofInstant(record.getInstant(), ZoneId.systemDefault())))
                    .append(' ').append(record.getLevel().getName()).append(' ')
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
