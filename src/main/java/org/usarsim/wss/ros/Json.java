package org.usarsim.wss.ros;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * JSON by hand, in one place: a strict, bounded parser (RFC 8259) and a writer.
 *
 * <p>{@link #parse} gives a {@code Map<String, Object>} (a {@link LinkedHashMap}, in the text's
 * order) for an object, a {@code List<Object>} for an array, a {@link String}, a {@link Double}
 * (always finite) for a number, a {@link Boolean}, and Java {@code null} for {@code null}. It
 * refuses, with a {@link JsonException} naming the offset: a text over the size limit, nesting
 * over the depth limit, a number that is not finite once read ({@code 1e999}), any escape but the
 * nine of RFC 8259 ({@code \/} and {@code \}{@code uXXXX} included; a surrogate escape must be
 * one of a pair), a raw control char in a string, a duplicate key in an object, a truncated text
 * and anything after the value but white space. Unknown fields are no concern of the parser: the
 * readers ({@link JsonNode}) take the fields they need and leave the rest.
 */
public final class Json {

    /** The largest depth a {@link JsonLimits} may allow: the parser recurses once per level. */
    static final int DEPTH_CEILING = 1000;
    /** The Doubles of the small integers, shared: an occupancy grid's 4 million cells are -1 to 100. */
    private static final Double[] SMALL = new Double[256];

    static {
        for (int i = 0; i < SMALL.length; i++) {
            SMALL[i] = (double) (i - 128);
        }
    }

    private final String text;
    private final int maxDepth;
    private int at;

    private Json(String text, int maxDepth) {
        this.text = text;
        this.maxDepth = maxDepth;
    }

    /**
     * The value of a JSON text, as described above.
     *
     * @throws JsonException the text is not strict JSON or is over a limit; the message names the offset
     */
    public static Object parse(String text, JsonLimits limits) throws JsonException {
        if (text.length() > limits.maxChars()) {
            throw JsonException.at(limits.maxChars(), "the text is " + text.length() + " chars, over the limit of " + limits.maxChars());
        }
        Json parser = new Json(text, Math.min(limits.maxDepth(), DEPTH_CEILING));
        parser.skipSpace();
        Object value = parser.value(0);
        parser.skipSpace();
        if (parser.at < text.length()) {
            throw JsonException.at(parser.at, "unexpected " + parser.shown() + " after the value");
        }
        return value;
    }

    private Object value(int depth) throws JsonException {
        if (at >= text.length()) {
            throw truncated("a value");
        }
        char c = text.charAt(at);
        switch (c) {
            case '{':
                return object(depth + 1);
            case '[':
                return array(depth + 1);
            case '"':
                return string();
            case 't':
                return literal("true", Boolean.TRUE);
            case 'f':
                return literal("false", Boolean.FALSE);
            case 'n':
                return literal("null", null);
            default:
                if (c == '-' || (c >= '0' && c <= '9')) {
                    return number();
                }
                throw JsonException.at(at, "expected a value, found " + shown());
        }
    }

    private Map<String, Object> object(int depth) throws JsonException {
        enter(depth);
        Map<String, Object> object = new LinkedHashMap<>();
        at++;
        skipSpace();
        if (peek() == '}') {
            at++;
            return object;
        }
        while (true) {
            if (peek() != '"') {
                throw expected("a key in quotes");
            }
            int keyAt = at;
            String key = string();
            skipSpace();
            if (peek() != ':') {
                throw expected("':'");
            }
            at++;
            skipSpace();
            Object value = value(depth);
            if (object.containsKey(key)) {
                throw JsonException.at(keyAt, "the key \"" + JsonException.shortened(key) + "\" twice in one object");
            }
            object.put(key, value);
            skipSpace();
            char c = peek();
            at++;
            if (c == '}') {
                return object;
            }
            if (c != ',') {
                at--;
                throw expected("',' or '}'");
            }
            skipSpace();
        }
    }

    private List<Object> array(int depth) throws JsonException {
        enter(depth);
        List<Object> array = new ArrayList<>();
        at++;
        skipSpace();
        if (peek() == ']') {
            at++;
            return array;
        }
        while (true) {
            array.add(value(depth));
            skipSpace();
            char c = peek();
            at++;
            if (c == ']') {
                return array;
            }
            if (c != ',') {
                at--;
                throw expected("',' or ']'");
            }
            skipSpace();
        }
    }

    private void enter(int depth) throws JsonException {
        if (depth > maxDepth) {
            throw JsonException.at(at, "nested deeper than the limit of " + maxDepth);
        }
    }

    private String string() throws JsonException {
        int start = ++at;
        // The common case, no escape: one substring.
        while (at < text.length()) {
            char c = text.charAt(at);
            if (c == '"') {
                return text.substring(start, at++);
            }
            if (c == '\\') {
                break;
            }
            if (c < 0x20) {
                throw JsonException.at(at, "a raw control char " + shown() + " in a string");
            }
            at++;
        }
        StringBuilder out = new StringBuilder(text.length() - start).append(text, start, at);
        while (at < text.length()) {
            char c = text.charAt(at);
            if (c == '"') {
                at++;
                return out.toString();
            }
            if (c < 0x20) {
                throw JsonException.at(at, "a raw control char " + shown() + " in a string");
            }
            if (c != '\\') {
                out.append(c);
                at++;
                continue;
            }
            int escapeAt = at++;
            if (at >= text.length()) {
                break;
            }
            char e = text.charAt(at++);
            switch (e) {
                case '"', '\\', '/' -> out.append(e);
                case 'b' -> out.append('\b');
                case 'f' -> out.append('\f');
                case 'n' -> out.append('\n');
                case 'r' -> out.append('\r');
                case 't' -> out.append('\t');
                case 'u' -> out.append(unicode(escapeAt));
                default -> throw JsonException.at(escapeAt, "a bad escape \\" + printable(e) + " in a string");
            }
        }
        throw truncated("the end of a string");
    }

    /** A {@code \}{@code uXXXX} escape (its backslash at {@code escapeAt}), a surrogate with its pair. */
    private char[] unicode(int escapeAt) throws JsonException {
        char c = hex4(escapeAt);
        if (Character.isLowSurrogate(c)) {
            throw JsonException.at(escapeAt, "a low surrogate escape without its high one");
        }
        if (!Character.isHighSurrogate(c)) {
            return new char[] {c};
        }
        if (at + 1 < text.length() && text.charAt(at) == '\\' && text.charAt(at + 1) == 'u') {
            int lowAt = at;
            at += 2;
            char low = hex4(lowAt);
            if (Character.isLowSurrogate(low)) {
                return new char[] {c, low};
            }
        }
        throw JsonException.at(escapeAt, "a high surrogate escape without its low one");
    }

    private char hex4(int escapeAt) throws JsonException {
        if (at + 4 > text.length()) {
            throw truncated("four hex digits");
        }
        int value = 0;
        for (int i = 0; i < 4; i++) {
            int digit = Character.digit(text.charAt(at + i), 16);
            if (digit < 0 || text.charAt(at + i) > 'f') {
                throw JsonException.at(escapeAt, "a bad escape: \\u needs four hex digits");
            }
            value = value * 16 + digit;
        }
        at += 4;
        return (char) value;
    }

    private Double number() throws JsonException {
        int start = at;
        boolean negative = peek() == '-';
        if (negative) {
            at++;
        }
        int digitsStart = at;
        if (peek() == '0') {
            at++;
        } else if (!digits()) {
            throw expected("a digit");
        }
        int digitsEnd = at;
        boolean integer = true;
        if (peek() == '.') {
            integer = false;
            at++;
            if (!digits()) {
                throw expected("a digit after '.'");
            }
        }
        if (peek() == 'e' || peek() == 'E') {
            integer = false;
            at++;
            if (peek() == '+' || peek() == '-') {
                at++;
            }
            if (!digits()) {
                throw expected("a digit in the exponent");
            }
        }
        if (integer && digitsEnd - digitsStart <= 3) {
            int value = 0;
            for (int i = digitsStart; i < digitsEnd; i++) {
                value = value * 10 + text.charAt(i) - '0';
            }
            if (negative) {
                value = -value;
            }
            if (value >= -128 && value < 128 && !(negative && value == 0)) {
                return SMALL[value + 128];
            }
        }
        double value = Double.parseDouble(text.substring(start, at));
        if (Double.isInfinite(value)) {
            throw JsonException.at(start, "the number " + JsonException.shortened(text.substring(start, at)) + " is not finite");
        }
        return value;
    }

    /** One digit or more; false when there is none. */
    private boolean digits() {
        int start = at;
        while (at < text.length() && text.charAt(at) >= '0' && text.charAt(at) <= '9') {
            at++;
        }
        return at > start;
    }

    private Object literal(String word, Object value) throws JsonException {
        if (!text.startsWith(word, at)) {
            if (word.startsWith(text.substring(at, Math.min(text.length(), at + word.length())))) {
                throw truncated("'" + word + "'");
            }
            throw JsonException.at(at, "expected a value, found " + shown());
        }
        at += word.length();
        return value;
    }

    private void skipSpace() {
        while (at < text.length()) {
            char c = text.charAt(at);
            if (c != ' ' && c != '\t' && c != '\n' && c != '\r') {
                return;
            }
            at++;
        }
    }

    /** The char at the offset, or 0 at the end (never a char JSON allows where it is looked for). */
    private char peek() {
        return at < text.length() ? text.charAt(at) : 0;
    }

    private JsonException expected(String what) {
        if (at >= text.length()) {
            return truncated(what);
        }
        return JsonException.at(at, "expected " + what + ", found " + shown());
    }

    private JsonException truncated(String what) {
        return JsonException.at(text.length(), "the text ends where " + what + " was expected (truncated)");
    }

    private String shown() {
        return at < text.length() ? "'" + printable(text.charAt(at)) + "'" : "the end";
    }

    private static String printable(char c) {
        return c >= 0x20 && c < 0x7f ? String.valueOf(c) : String.format("\\u%04x", (int) c);
    }

    /**
     * The JSON text of a value: a {@code Map} with String keys, a {@code Collection}, a String, a
     * finite Number, a Boolean or null. Strings are quoted as RFC 8259 asks ({@code "}, the
     * backslash and the control chars escaped; {@code /} and non-ASCII as they are).
     *
     * @throws IllegalArgumentException a value of another kind, or a number that is not finite
     */
    public static String write(Object value) {
        StringBuilder out = new StringBuilder();
        write(value, out);
        return out.toString();
    }

    /** As {@link #write(Object)}, appended to {@code out}. */
    public static void write(Object value, StringBuilder out) {
        if (value == null) {
            out.append("null");
        } else if (value instanceof String s) {
            quote(s, out);
        } else if (value instanceof Boolean b) {
            out.append(b.booleanValue());
        } else if (value instanceof Double || value instanceof Float) {
            double d = ((Number) value).doubleValue();
            if (!Double.isFinite(d)) {
                throw new IllegalArgumentException("JSON has no " + d);
            }
            out.append(d);
        } else if (value instanceof Integer || value instanceof Long || value instanceof Short || value instanceof Byte) {
            out.append(((Number) value).longValue());
        } else if (value instanceof Map<?, ?> map) {
            out.append('{');
            boolean first = true;
            for (Map.Entry<?, ?> entry : map.entrySet()) {
                if (!(entry.getKey() instanceof String key)) {
                    throw new IllegalArgumentException("a JSON key is a string, not " + entry.getKey());
                }
                if (!first) {
                    out.append(',');
                }
                first = false;
                quote(key, out);
                out.append(':');
                write(entry.getValue(), out);
            }
            out.append('}');
        } else if (value instanceof Collection<?> list) {
            out.append('[');
            boolean first = true;
            for (Object item : list) {
                if (!first) {
                    out.append(',');
                }
                first = false;
                write(item, out);
            }
            out.append(']');
        } else {
            throw new IllegalArgumentException("no JSON for a " + value.getClass().getName());
        }
    }

    /** A string in quotes, escaped as RFC 8259 asks. */
    public static String quote(String s) {
        StringBuilder out = new StringBuilder(s.length() + 2);
        quote(s, out);
        return out.toString();
    }

    private static void quote(String s, StringBuilder out) {
        out.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> out.append("\\\"");
                case '\\' -> out.append("\\\\");
                case '\n' -> out.append("\\n");
                case '\r' -> out.append("\\r");
                case '\t' -> out.append("\\t");
                default -> {
                    if (c < 0x20) {
                        out.append(String.format("\\u%04x", (int) c));
                    } else {
                        out.append(c);
                    }
                }
            }
        }
        out.append('"');
    }
}
