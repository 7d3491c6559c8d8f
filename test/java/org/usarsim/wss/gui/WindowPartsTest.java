package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import javax.swing.JTextArea;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The window's parts that need no server: the filter's wildcards, the log's lines and its bound. */
@Tag("slow")
class WindowPartsTest {

    @Test
    void theFilterIsACaseInsensitiveWildcardFoundAnywhere() {
        assertTrue(WildcardFilter.pattern("r1").matcher("R1 r2").find());
        assertTrue(WildcardFilter.pattern("R2 *1").matcher("r2 robot1").find());
        assertTrue(WildcardFilter.pattern("r?").matcher("x r5").find());
        assertFalse(WildcardFilter.pattern("r1 r3").matcher("r1 r2").find());
        assertTrue(WildcardFilter.pattern("a.b(").matcher("a.b( c").find(), "other characters are literal");
        assertFalse(WildcardFilter.pattern("a.b").matcher("axb c").find());
        assertEquals(null, WildcardFilter.of("  "));
    }

    @Test
    void logLinesAreTheOriginalsAndTheQueueDropsTheOldest() {
        WindowLog log = new WindowLog();
        log.publish(new LogRecord(Level.INFO, "registered r1"));
        log.publish(new LogRecord(Level.FINE, "a detail"));
        log.publish(new LogRecord(Level.WARNING, "refused"));
        log.publish(new LogRecord(Level.SEVERE, "no thread"));
        assertEquals(List.of("debug: registered r1", "debug: a detail", "WARNING: refused", "WARNING: no thread"), log.drain());
        assertEquals(List.of(), log.drain());
        for (int i = 0; i < WindowLog.MAX_QUEUED + 10; i++) {
            log.publish(new LogRecord(Level.INFO, "line " + i));
        }
        List<String> lines = log.drain();
        assertEquals(WindowLog.MAX_QUEUED + 1, lines.size());
        assertEquals("WARNING: 10 log lines were dropped: they came faster than the window shows them", lines.get(0));
        assertEquals("debug: line 10", lines.get(1));
    }

    @Test
    void theJdksOwnRecordsStayOutAndControlCharactersAreEscaped() {
        WindowLog log = new WindowLog();
        LogRecord prefs = new LogRecord(Level.INFO, "Created user preferences directory.");
        prefs.setLoggerName("java.util.prefs");
        log.publish(prefs);
        LogRecord awt = new LogRecord(Level.WARNING, "a font");
        awt.setLoggerName("sun.awt.X11.XToolkit");
        log.publish(awt);
        LogRecord ours = new LogRecord(Level.INFO, "registered E\u001b[2J");
        ours.setLoggerName("org.usarsim.wss.hub.EventLogger");
        log.publish(ours);
        LogRecord plugin = new LogRecord(Level.INFO, "a plugin's line");
        plugin.setLoggerName("com.example.MyModel");
        log.publish(plugin);
        assertEquals(List.of("debug: registered E\\u001B[2J", "debug: a plugin's line"), log.drain());
    }

    @Test
    void theLogPanelKeepsTheNewestLines() {
        Gui.requireDisplay();
        String text = Gui.onEdt(() -> {
            LogPanel panel = new LogPanel();
            for (int batch = 0; batch < 5; batch++) {
                List<String> lines = new ArrayList<>();
                for (int i = 0; i < 1000; i++) {
                    lines.add("debug: line " + (batch * 1000 + i));
                }
                panel.append(lines);
            }
            return Gui.find(panel, JTextArea.class, "log").getText();
        });
        String[] lines = text.split("\n");
        assertEquals(LogPanel.MAX_LINES, lines.length);
        assertEquals("debug: line " + (5000 - LogPanel.MAX_LINES), lines[0]);
        assertEquals("debug: line 4999", lines[lines.length - 1]);
    }
}
