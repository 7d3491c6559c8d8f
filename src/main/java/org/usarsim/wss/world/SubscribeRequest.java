package org.usarsim.wss.world;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.usarsim.wss.ros.Json;

/**
 * A {@code subscribe} op's fields, checked as rosbridge_library 0.11.17's
 * {@code Subscribe.subscribe} checks them (capabilities/subscribe.py, capability.py's
 * {@code basic_type_check}), in its order: {@code topic} (required) and {@code type} strings;
 * {@code throttle_rate}, {@code fragment_size} and {@code queue_length} Python ints (a JSON
 * integer or a boolean: {@code 100.0} is a float, refused); {@code compression} a string. Absent:
 * throttle_rate and queue_length 0, compression {@code none}. The id is any JSON value (null when
 * absent), but an object or an array cannot be a key of rosbridge's dict of ids.
 *
 * @param id the op's id, null without one
 * @param type the type asked, null without one
 */
record SubscribeRequest(Object id, String topic, String type, long throttleMs, long queueLength, String compression) {

    /** A request rosbridge refuses, with its exception's text. */
    static final class Refused extends Exception {
        Refused(String message) {
            super(message);
        }
    }

    private static final String STR = "(<class 'str'>,)";
    private static final String INT = "(<class 'int'>,)";

    /**
     * The fields of a request object.
     *
     * @param integers its fields written as JSON integers ({@link IntegerFields})
     * @throws Refused a field missing or of the wrong kind, or an id that is an object or an array
     */
    static SubscribeRequest of(Map<String, Object> fields, Set<String> integers) throws Refused {
        if (!fields.containsKey("topic")) {
            throw new Refused("Expected a topic field but none was found.");
        }
        String topic = (String) checked(fields, integers, "topic", STR, fields.get("topic") instanceof String);
        String type = (String) checked(fields, integers, "type", STR, fields.get("type") instanceof String);
        long throttle = integer(fields, integers, "throttle_rate");
        integer(fields, integers, "fragment_size");
        long queue = integer(fields, integers, "queue_length");
        String compression = (String) checked(fields, integers, "compression", STR, fields.get("compression") instanceof String);
        Object id = fields.get("id");
        if (id instanceof Map || id instanceof List) {
            throw new Refused("unhashable type: '" + (id instanceof Map ? "dict" : "list") + "'");
        }
        return new SubscribeRequest(id, topic, type, throttle, queue, compression == null ? "none" : compression);
    }

    /** A field's value (null when absent) when it is of its kind ({@code ok}). */
    private static Object checked(Map<String, Object> fields, Set<String> integers, String name, String kinds, boolean ok)
            throws Refused {
        if (fields.containsKey(name) && !ok) {
            Object value = fields.get(name);
            throw new Refused("Expected field " + name + " to be one of " + kinds + ". Invalid value: "
                    + (integers.contains(name) ? String.valueOf(((Double) value).longValue()) : python(value)));
        }
        return fields.get(name);
    }

    /** A Python int field's value, 0 when absent. */
    private static long integer(Map<String, Object> fields, Set<String> integers, String name) throws Refused {
        Object value = checked(fields, integers, name, INT, fields.get(name) instanceof Boolean
                || fields.get(name) instanceof Double && integers.contains(name));
        if (value instanceof Boolean b) {
            return b ? 1 : 0;
        }
        // a Double's long value saturates at Long's bounds
        return value == null ? 0 : ((Double) value).longValue();
    }

    /** A value as Python's str() writes it, near enough for a log line. */
    static String python(Object value) {
        if (value == null) {
            return "None";
        }
        if (value instanceof Boolean b) {
            return b ? "True" : "False";
        }
        if (value instanceof String s) {
            return s;
        }
        if (value instanceof Double d && Math.abs(d) < 1e16) {
            return Fragments.pythonFloat(d);
        }
        return Json.write(value);
    }
}
