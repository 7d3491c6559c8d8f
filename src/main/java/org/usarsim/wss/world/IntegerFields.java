package org.usarsim.wss.world;

import java.util.HashSet;
import java.util.Set;
import org.usarsim.wss.ros.Json;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;

/**
 * Which fields of a JSON object are written as integers ({@code 100}, {@code -5}): rosbridge reads
 * its requests with Python's json, which makes those an {@code int} and {@code 100.0} or
 * {@code 1e2} a {@code float}, and its type checks tell them apart ({@code throttle_rate} must be
 * an int); the project's JSON reader gives every number as a Double. Of a field written twice, the
 * last counts, as in both readers.
 */
final class IntegerFields {

    private IntegerFields() {
    }

    /**
     * The top-level fields of an object written as integers.
     *
     * @param text a JSON object's text, already read without error by {@link Json#parse}
     */
    static Set<String> of(String text) throws JsonException {
        Set<String> integers = new HashSet<>();
        int at = space(text, space(text, 0) + 1);
        while (text.charAt(at) != '}') {
            int keyEnd = stringEnd(text, at);
            String key = (String) Json.parse(text.substring(at, keyEnd), JsonLimits.DEFAULT);
            int value = space(text, space(text, keyEnd) + 1);
            int end = valueEnd(text, value);
            if (text.substring(value, end).matches("-?[0-9]+")) {
                integers.add(key);
            } else {
                integers.remove(key);
            }
            at = space(text, end);
            if (text.charAt(at) == ',') {
                at = space(text, at + 1);
            }
        }
        return integers;
    }

    private static int space(String text, int at) {
        while (at < text.length() && " \t\r\n".indexOf(text.charAt(at)) >= 0) {
            at++;
        }
        return at;
    }

    /** Just after the string that starts at {@code at}. */
    private static int stringEnd(String text, int at) {
        int i = at + 1;
        while (text.charAt(i) != '"') {
            i += text.charAt(i) == '\\' ? 2 : 1;
        }
        return i + 1;
    }

    /** Just after the value that starts at {@code at}. */
    private static int valueEnd(String text, int at) {
        char c = text.charAt(at);
        if (c == '"') {
            return stringEnd(text, at);
        }
        if (c == '{' || c == '[') {
            int depth = 0;
            int i = at;
            do {
                char d = text.charAt(i);
                if (d == '"') {
                    i = stringEnd(text, i);
                    continue;
                }
                depth += d == '{' || d == '[' ? 1 : d == '}' || d == ']' ? -1 : 0;
                i++;
            } while (depth > 0);
            return i;
        }
        int i = at;
        while (i < text.length() && ",}] \t\r\n".indexOf(text.charAt(i)) < 0) {
            i++;
        }
        return i;
    }
}
