package org.usarsim.wss.world;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Supplier;
import java.util.logging.Level;
import org.usarsim.wss.ros.Json;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.JsonNode;

/**
 * One rosbridge v2 client's requests and what the world server does about them, as a real
 * rosbridge (rosbridge_suite 0.11) does: {@code subscribe} (topic, type, throttle_rate,
 * queue_length, id) and {@code unsubscribe} kept in {@link Subscriptions}; {@code /map} sent at
 * once on subscribe, as a latched topic is, the others at the ticks they are due
 * ({@link #tick}); {@code call_service} answered that the service does not exist (the world
 * server offers none). A bad request gets no answer, only a log line, as rosbridge only logs it:
 * malformed JSON, no {@code op}, an unknown op, a topic the world does not publish without a
 * type, a type that is not the topic's. A request the client may send but the world server does
 * not serve ({@code advertise}, {@code publish}, ...) is logged too. No sockets: what it sends
 * and logs goes to its {@link Out}.
 */
final class RosbridgeSession {

    /** The longest request taken, in chars (the WebSocket layer has already limited its bytes). */
    static final JsonLimits LIMITS = new JsonLimits(RosbridgeServer.MAX_MESSAGE_BYTES, JsonLimits.DEFAULT_MAX_DEPTH);

    /** Where a session's frames and log lines go. */
    interface Out {
        void send(String frame);

        /** A line through the server's limit on client-caused lines, of this kind. */
        void log(Level level, String kind, String message);
    }

    private final Subscriptions subscriptions = new Subscriptions();
    private final Supplier<Snapshot> world;
    private final Supplier<String> map;
    private final Out out;
    private long seq;

    /**
     * @param world the world now (for the topics it has)
     * @param map the {@code /map} frame (made once per server)
     */
    RosbridgeSession(Supplier<Snapshot> world, Supplier<String> map, Out out) {
        this.world = world;
        this.map = map;
        this.out = out;
    }

    /** One text message from the client. */
    void request(String text) {
        JsonNode request;
        try {
            request = JsonNode.parse(text, LIMITS);
            if (!request.isObject()) {
                throw request.problem("expected an object, found " + (request.value() == null ? "null" : "another value"));
            }
        } catch (JsonException e) {
            out.log(Level.WARNING, "malformed requests", "malformed JSON: " + e.getMessage());
            return;
        }
        try {
            JsonNode op = request.optional("op");
            String id = idOf(request);
            if (op == null) {
                out.log(Level.WARNING, "requests without an op", "Received a message without an op: " + shortened(text));
                return;
            }
            switch (op.string()) {
                case "subscribe" -> subscribe(request, id);
                case "unsubscribe" -> unsubscribe(request, id);
                case "call_service" -> callService(request, id);
                case "advertise", "unadvertise", "publish", "fragment", "advertise_service", "service_response",
                        "unadvertise_service" -> out.log(Level.INFO, "unserved operations",
                                prefix(id) + op.string() + " is not served by the world server: it only publishes");
                default -> out.log(Level.WARNING, "unknown operations", prefix(id) + "Unknown operation: " + shortened(op.string()));
            }
        } catch (JsonException e) {
            out.log(Level.WARNING, "malformed requests", "a request with " + e.getMessage());
        }
    }

    private void subscribe(JsonNode request, String id) throws JsonException {
        String topic = request.get("topic").string();
        JsonNode typeNode = request.optional("type");
        String type = typeNode == null || typeNode.isNull() ? null : typeNode.string();
        JsonNode throttleNode = request.optional("throttle_rate");
        long throttleMs = throttleNode == null ? 0 : throttleNode.integer(0, Integer.MAX_VALUE);
        JsonNode queue = request.optional("queue_length");
        if (queue != null) {
            queue.integer(0, Integer.MAX_VALUE);
        }
        String published = RosbridgeMessages.topics(world.get()).get(topic);
        if (published == null) {
            if (type == null) {
                out.log(Level.WARNING, "bad subscriptions", prefix(id) + "subscribe: Cannot infer topic type for topic "
                        + shortened(topic) + " as it is not yet advertised");
            } else {
                out.log(Level.INFO, "subscriptions to unknown topics", prefix(id) + "subscribe: " + shortened(topic)
                        + " is not published by the world server: nothing will come");
            }
            return;
        }
        if (type != null && !plain(type).equals(published)) {
            out.log(Level.WARNING, "bad subscriptions", prefix(id) + "subscribe: Tried to register topic " + topic
                    + " with type " + shortened(type) + " but it is already established with type " + published);
            return;
        }
        out.log(Level.INFO, "subscriptions", "subscribed to " + topic + " (" + published + ", throttle_rate " + throttleMs + " ms)");
        if (topic.equals(RosbridgeMessages.MAP)) {
            out.send(map.get());
            return;
        }
        subscriptions.subscribe(new Subscriptions.Subscription(topic, published, throttleMs * 1_000_000L, id));
    }

    private void unsubscribe(JsonNode request, String id) throws JsonException {
        String topic = request.get("topic").string();
        if (!subscriptions.unsubscribe(topic) && !topic.equals(RosbridgeMessages.MAP)) {
            out.log(Level.INFO, "unsubscriptions", prefix(id) + "unsubscribe: not subscribed to " + shortened(topic));
        }
    }

    private void callService(JsonNode request, String id) throws JsonException {
        String service = request.get("service").string();
        out.log(Level.INFO, "service calls", prefix(id) + "call_service InvalidServiceException: Service " + shortened(service)
                + " does not exist");
        Map<String, Object> response = new LinkedHashMap<>();
        response.put("op", "service_response");
        response.put("service", service);
        response.put("values", "Service " + service + " does not exist");
        response.put("result", false);
        if (id != null) {
            response.put("id", id);
        }
        out.send(Json.write(response));
    }

    /** Sends what is due at a tick ({@code nanos}: its time, for the throttle rates), the world at {@code seconds}. */
    void tick(long nanos, Snapshot now, double seconds) {
        for (Subscriptions.Subscription due : subscriptions.due(nanos)) {
            String frame = RosbridgeMessages.publish(due.topic(), now, seconds, seq);
            if (frame != null) {
                out.send(frame);
            }
        }
        seq++;
    }

    int subscriptionCount() {
        return subscriptions.size();
    }

    /** The request's id when it is a string (rosbridge's ids are), or null. */
    private static String idOf(JsonNode request) throws JsonException {
        JsonNode id = request.optional("id");
        return id == null || !(id.value() instanceof String) ? null : id.string();
    }

    private static String prefix(String id) {
        return id == null ? "" : "[id: " + shortened(id) + "] ";
    }

    /** A ROS type name without ROS 2's {@code /msg/}. */
    private static String plain(String type) {
        return type.replace("/msg/", "/");
    }

    private static String shortened(String text) {
        return text.length() <= 200 ? text : text.substring(0, 200) + "...";
    }
}
