package org.usarsim.wss.ros;

/**
 * One rosbridge v2 text frame: its {@code op} ({@code publish}, {@code status},
 * {@code service_response}, ...; null when it has none), its {@code topic} (null when it has
 * none) and the whole frame. Only {@code publish} frames carry a message.
 */
public record RosFrame(String op, String topic, JsonNode root) {

    /**
     * Parses a frame; it must be a JSON object, with {@code op} and {@code topic} strings where
     * present.
     */
    public static RosFrame parse(String text, JsonLimits limits) throws JsonException {
        JsonNode root = JsonNode.parse(text, limits);
        if (!root.isObject()) {
            throw root.wrong("an object");
        }
        JsonNode op = root.optional("op");
        JsonNode topic = root.optional("topic");
        return new RosFrame(op == null ? null : op.string(), topic == null ? null : topic.string(), root);
    }

    public boolean isPublish() {
        return "publish".equals(op);
    }

    /** A publish frame's message ({@code msg}, an object). */
    public JsonNode msg() throws JsonException {
        JsonNode msg = root.get("msg");
        if (!msg.isObject()) {
            throw msg.wrong("an object");
        }
        return msg;
    }
}
