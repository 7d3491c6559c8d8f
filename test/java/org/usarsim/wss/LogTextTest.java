package org.usarsim.wss;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import org.junit.jupiter.api.Test;

/** What a log line may not carry raw: control, separator and format characters, escaped as \\uXXXX. */
class LogTextTest {

    @Test
    void terminalEscapesAndOtherControlsAreWrittenAsTheirEscapes() {
        assertEquals("registered E\\u001B[2J\\u001B[31mroot", LogText.escape("registered E\u001b[2J\u001b[31mroot"));
        assertEquals("a\\u000Db \\u0009 \\u0000 \\u007F \\u009B6n \\u0085", LogText.escape("a\rb \t \u0000 \u007f \u009b6n \u0085"));
    }

    @Test
    void invisibleReorderingAndSeparatorsAreEscapedToo() {
        assertEquals("R\\u202Egnp.exe \\u2028 \\u200B", LogText.escape("R\u202egnp.exe \u2028 \u200b"));
    }

    @Test
    void printableTextAndTheLineFeedOfATableStayAsTheyAre() {
        String text = "link statistics, 1 pair\nMüller - 東京 up  -71.2549 ü ß € {Robot R1}";
        assertSame(text, LogText.escape(text), "nothing to escape: the same string");
        assertEquals(null, LogText.escape(null));
    }
}
