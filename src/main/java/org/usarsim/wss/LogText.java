package org.usarsim.wss;

/**
 * The text of a log line as it is written, in the one rule both logs follow (the headless log's
 * formatter, {@code app.LogSetup}, and the window's, {@code gui.WindowLog}): names and lines that
 * clients send reach the log, so a character that a terminal or a viewer would obey instead of
 * showing is written as its escape {@code \}{@code uXXXX}: the control characters (C0, DEL, C1;
 * {@code INIT {Robot E<ESC>[2J}} would clear the screen of whoever reads the log), the line and
 * paragraph separators, and the invisible format characters (the bidirectional overrides among
 * them, which reorder what follows). The line feed stays: the one record of several lines (the
 * link statistics table) is the server's own.
 */
public final class LogText {

    private LogText() {
    }

    /** The text with every such character escaped; the same string when there is none. */
    public static String escape(String text) {
        if (text == null) {
            return null;
        }
        int first = 0;
        while (first < text.length() && !escaped(text.charAt(first))) {
            first++;
        }
        if (first == text.length()) {
            return text;
        }
        StringBuilder out = new StringBuilder(text.length() + 16).append(text, 0, first);
        for (int i = first; i < text.length(); i++) {
            char c = text.charAt(i);
            if (escaped(c)) {
                out.append(String.format("\\u%04X", (int) c));
            } else {
                out.append(c);
            }
        }
        return out.toString();
    }

    private static boolean escaped(char c) {
        if (c == '\n') {
            return false;
        }
        if (c < 0x20 || (c >= 0x7F && c <= 0x9F)) {
            return true;
        }
        if (c < 0xA0) {
            return false;
        }
        int type = Character.getType(c);
        return type == Character.FORMAT || type == Character.LINE_SEPARATOR || type == Character.PARAGRAPH_SEPARATOR;
    }
}
