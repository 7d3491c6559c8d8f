package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
}
