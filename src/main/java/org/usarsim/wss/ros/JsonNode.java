package org.usarsim.wss.ros;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * A parsed JSON value with its path from the frame's root ({@code msg.pose[2].position.x}), read
 * field by field: each reader checks the kind and throws a {@link JsonException} naming the path
 * and what it found ({@code msg.pose[2].position.x: expected a number, found null}). Fields it is
 * not asked for are never looked at, so unknown fields are ignored.
 */
public final class JsonNode {

    private final Object value;
    private final String path;

    private JsonNode(Object value, String path) {
        this.value = value;
        this.path = path;
    }

    /** The root of a parsed value (its path is empty). */
    public static JsonNode root(Object parsed) {
        return new JsonNode(parsed, "");
    }

    /** Parses a text into its root node. */
    public static JsonNode parse(String text, JsonLimits limits) throws JsonException {
        return root(Json.parse(text, limits));
    }

    /** The value as {@link Json#parse} gave it. */
    public Object value() {
        return value;
    }

    public String path() {
        return path;
    }

    public boolean isNull() {
        return value == null;
    }

    public boolean isObject() {
        return value instanceof Map;
    }

    /** Whether this is an object that has the field (null or not). */
    public boolean has(String key) {
        return value instanceof Map<?, ?> map && map.containsKey(key);
    }

    /** The field of an object; an error when this is no object or the field is missing. */
    public JsonNode get(String key) throws JsonException {
        Map<?, ?> map = object();
        if (!map.containsKey(key)) {
            throw JsonException.in(child(key), "missing");
        }
        return new JsonNode(map.get(key), child(key));
    }

    /** The field of an object, or null when it is missing; an error when this is no object. */
    public JsonNode optional(String key) throws JsonException {
        Map<?, ?> map = object();
        return map.containsKey(key) ? new JsonNode(map.get(key), child(key)) : null;
    }

    /** The items of an array. */
    public List<JsonNode> items() throws JsonException {
        List<?> list = list();
        List<JsonNode> items = new ArrayList<>(list.size());
        for (int i = 0; i < list.size(); i++) {
            items.add(new JsonNode(list.get(i), path + "[" + i + "]"));
        }
        return items;
    }

    /** The array's values as Json gave them (no node per item: an occupancy grid has millions). */
    public List<?> list() throws JsonException {
        if (value instanceof List<?> list) {
            return list;
        }
        throw wrong("an array");
    }

    public String string() throws JsonException {
        if (value instanceof String s) {
            return s;
        }
        throw wrong("a string");
    }

    public double number() throws JsonException {
        if (value instanceof Double d) {
            return d;
        }
        throw wrong("a number");
    }

    /** A number that is a whole number from {@code min} to {@code max}. */
    public long integer(long min, long max) throws JsonException {
        double d = number();
        if (d != Math.rint(d) || d < min || d > max) {
            throw JsonException.in(path, "expected a whole number from " + min + " to " + max + ", found " + d);
        }
        return (long) d;
    }

    public boolean bool() throws JsonException {
        if (value instanceof Boolean b) {
            return b;
        }
        throw wrong("true or false");
    }

    private Map<?, ?> object() throws JsonException {
        if (value instanceof Map<?, ?> map) {
            return map;
        }
        throw wrong("an object");
    }

    private String child(String key) {
        return path.isEmpty() ? key : path + "." + key;
    }

    /** The error for a value of the wrong kind here. */
    JsonException wrong(String expected) {
        return JsonException.in(path, "expected " + expected + ", found " + kind(value));
    }

    /** An error about the value here. */
    public JsonException problem(String problem) {
        return JsonException.in(path, problem);
    }

    static String kind(Object value) {
        if (value == null) {
            return "null";
        }
        if (value instanceof Map) {
            return "an object";
        }
        if (value instanceof List) {
            return "an array";
        }
        if (value instanceof String) {
            return "a string";
        }
        if (value instanceof Boolean) {
            return value.toString();
        }
        return "a number";
    }
}
