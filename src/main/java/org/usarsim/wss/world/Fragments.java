package org.usarsim.wss.world;

import org.usarsim.wss.Decimals;
import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.List;
import org.usarsim.wss.ros.Json;

/**
 * A connection's {@code fragment_size} and what it does to the frames sent, as rosbridge_library
 * 0.11.17 has it (protocol.py, capabilities/fragmentation.py). It is the connection's, not a
 * subscription's: any request of a known op that has the key sets it, before the op runs (even
 * one that then fails), for every later frame; nothing resets it but another value ({@code null}:
 * no fragments again). A frame whose JSON text (non-ASCII escaped, as Python's json writes it) is
 * longer than the size goes as fragment ops, {@code {"op":"fragment","id":ID,"data":...,"num":i,
 * "total":T}}: {@code data} the text's consecutive substrings of {@code fragment_size} chars,
 * {@code num} from 0, {@code total} Python 3's true division {@code (len - 1) / size + 1} (a
 * float: 3.95 for 60 chars in 20s), {@code ID} the frame's id, 0 when it has none (every publish).
 * A value rosbridge cannot fragment with (not a whole number above 0: 0, -5, 100.0, "x") makes
 * each frame longer than it fail in rosbridge's send: none is sent.
 */
final class Fragments {

    /** The size when it is a whole number (a JSON boolean is Python's 0 or 1); else null. */
    private Long size;
    /** The value as the request gave it, null when there is none (or it was null): no fragments. */
    private Object value;
    /** Whether the value was written as a JSON integer (Python's int), not {@code 100.0}. */
    private boolean integer;

    /** A request's {@code fragment_size}, as parsed ({@code integer}: written as a JSON integer or a boolean). */
    void set(Object value, boolean integer) {
        this.value = value;
        this.integer = integer;
        if (value instanceof Boolean b) {
            size = b ? 1L : 0L;
        } else if (value instanceof Double d && integer) {
            size = d >= Long.MAX_VALUE ? Long.MAX_VALUE : d <= Long.MIN_VALUE ? Long.MIN_VALUE : d.longValue();
        } else {
            size = null;
        }
    }

    /**
     * What goes out for a frame: itself, its fragment ops, or nothing (rosbridge's send fails);
     * {@code id} is the frame's id (null: none).
     */
    List<String> of(String frame, Object id) {
        if (value == null) {
            return List.of(frame);
        }
        String text = ascii(frame);
        int length = text.length();
        if (size == null) {
            // a float compares (a longer frame then fails to split); anything else fails to compare
            return !integer && value instanceof Double d && length <= d ? List.of(frame) : List.of();
        }
        if (length <= size) {
            return List.of(frame);
        }
        if (size <= 0) {
            return List.of();
        }
        int step = (int) Math.min(size, Integer.MAX_VALUE);
        String total = pythonFloat((double) (length - 1) / step + 1);
        String head = "{\"op\":\"fragment\",\"id\":" + Json.write(id == null ? 0 : id) + ",\"data\":";
        List<String> fragments = new ArrayList<>();
        for (int at = 0, num = 0; at < length; at += step, num++) {
            fragments.add(head + Json.quote(text.substring(at, Math.min(length, at + step))) + ",\"num\":" + num + ",\"total\":"
                    + total + "}");
        }
        return fragments;
    }

    /** What the log says of the value. */
    String describe() {
        return value == null ? "None" : value instanceof Double d && integer ? String.valueOf(d.longValue()) : Json.write(value);
    }

    /** The text with every char beyond ASCII written {@code \\uXXXX}, as Python's json writes it. */
    static String ascii(String text) {
        if (text.chars().allMatch(c -> c < 0x80)) {
            return text;
        }
        StringBuilder out = new StringBuilder(text.length() + 16);
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c < 0x80) {
                out.append(c);
            } else {
                out.append(String.format("\\u%04x", (int) c));
            }
        }
        return out.toString();
    }

    /** A float as Python's repr writes it (the shortest digits that read back as it), for a finite value below 1e16. */
    static String pythonFloat(double value) {
        BigDecimal exact = new BigDecimal(value);
        for (int digits = 1; digits <= 17; digits++) {
            BigDecimal shortest = exact.round(new MathContext(digits));
            if (shortest.doubleValue() == value) {
                String plain = Decimals.plain(shortest);
                return plain.contains(".") ? plain : plain + ".0";
            }
        }
        throw new AssertionError(value);
    }
}
