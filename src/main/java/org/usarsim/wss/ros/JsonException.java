package org.usarsim.wss.ros;

import org.usarsim.wss.LogText;

/**
 * JSON that is not what was expected: text that is not strict JSON (RFC 8259) or over a
 * {@link JsonLimits} limit, with the offset of the first char found wrong, or a value of the
 * wrong kind in a message, with its path ({@code msg.pose[2].position.x: expected a number,
 * found null}). Its message is one short line, fit for the log.
 */
public final class JsonException extends Exception {

    private static final long serialVersionUID = 1L;

    private final int offset;

    /** A problem in the text at {@code offset} (chars from its start). */
    static JsonException at(int offset, String problem) {
        return new JsonException("at offset " + offset + ": " + problem, offset);
    }

    /** A problem with the value at {@code path} in a parsed message. */
    static JsonException in(String path, String problem) {
        return new JsonException((path.isEmpty() ? "the frame" : path) + ": " + problem, -1);
    }

    /**
     * A value of the text as a message quotes it: at most 40 chars, then "...", on one line (the
     * line feed escaped as {@link LogText} escapes the other control chars).
     */
    static String shortened(String value) {
        String cut = value.length() <= 40 ? value : value.substring(0, 40) + "...";
        return LogText.escape(cut).replace("\n", "\\u000A");
    }

    private JsonException(String message, int offset) {
        super(message);
        this.offset = offset;
    }

    /** The offset in the text of the first char found wrong; -1 for a value of the wrong kind. */
    public int offset() {
        return offset;
    }
}
