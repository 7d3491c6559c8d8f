package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import org.junit.jupiter.api.Test;

/** The headless log's line: a client's name cannot put terminal escapes or a line of its own in it. */
class LogSetupTest {

    @Test
    void aNameWithEscapesIsWrittenEscapedOnOneLine() {
        LogRecord record = new LogRecord(Level.INFO, "registered E\u001b[2J\rWARNING fake from 127.0.0.1 accepting on [5000]");
        record.setThrown(new IllegalStateException("bad\u001b[0m\nsecond line"));
        String line = new LogSetup.OneLine().format(record);
        assertFalse(line.contains("\u001b"), line);
        assertFalse(line.contains("\r"), line);
        assertTrue(line.contains(" INFO registered E\\u001B[2J\\u000DWARNING fake from"), line);
        assertTrue(line.contains("(java.lang.IllegalStateException: bad\\u001B[0m second line at "), line);
        assertTrue(line.endsWith(System.lineSeparator()) && line.indexOf('\n') == line.length() - 1, "one line: " + line);
    }

    /** The time formatted once a second is the time the formatter writes, milliseconds and all, in and across seconds. */
    @Test
    void theTimeIsTheFormattersToTheMillisecond() {
        LogSetup.OneLine formatter = new LogSetup.OneLine();
        Instant start = Instant.parse("2026-11-25T14:59:59.000Z");
        for (long millis : new long[] {0, 7, 99, 100, 999, 1000, 1001, 1999, 61_050, 3_600_123}) {
            Instant at = start.plusMillis(millis);
            LogRecord record = new LogRecord(Level.INFO, "allocated");
            record.setInstant(at);
            String expected = LogSetup.TIME.format(LocalDateTime.ofInstant(at, ZoneId.systemDefault())) + " INFO allocated";
            assertEquals(expected + System.lineSeparator(), formatter.format(record), "at " + at);
        }
    }
}
