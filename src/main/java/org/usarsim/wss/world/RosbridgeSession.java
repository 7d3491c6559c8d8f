package org.usarsim.wss.world;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;
import java.util.logging.Level;
import org.usarsim.wss.ros.Json;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.JsonNode;

/**
 * One rosbridge v2 client's requests and what the world server does about them, as
 * rosbridge_suite 0.11.17 (rosbridge_library's protocol.py and capabilities) does:
 * {@code subscribe} and {@code unsubscribe} kept in {@link ClientSubscriptions} (ids, throttle
 * rates, queue lengths, latched topics, as rosbridge combines them), whose messages are sent as the
 * world's {@link RosGraph} publishes them ({@link #advance}); {@code fragment_size} in any request
 * of a known op, the connection's from then on ({@link Fragments}); {@code call_service} answered
 * that the service does not exist (the world server offers none). A bad request gets no answer,
 * only a log line, as rosbridge only logs it: malformed JSON, no {@code op}, an unknown op, a
 * subscribe whose fields are of the wrong kind (a {@code throttle_rate} of {@code 100.0}), a topic
 * the world does not publish without a type, a type that is not the topic's. A request the client
 * may send but the world server does not serve ({@code advertise}, {@code publish}, ...) is logged
 * too. No sockets, no clock: the world's time (nanoseconds) is passed in; what it sends and logs
 * goes to its {@link Out}.
 */
final class RosbridgeSession {

    /** The longest request taken, in chars (the WebSocket layer has already limited its bytes). */
    static final JsonLimits LIMITS = new JsonLimits(RosbridgeServer.MAX_MESSAGE_BYTES, JsonLimits.DEFAULT_MAX_DEPTH);

    /** rosbridge's ops besides subscribe, unsubscribe and call_service: known, and not served by the world server. */
    private static final Set<String> UNSERVED = Set.of("advertise", "unadvertise", "publish", "fragment", "advertise_service",
            "service_response", "unadvertise_service");

    /** Where a session's frames and log lines go. */
    interface Out {
        void send(String frame);

        /** A line through the server's limit on client-caused lines, of this kind. */
        void log(Level level, String kind, String message);
    }

    private final World world;
    private final RosGraph graph;
    private final Supplier<String> map;
    private final Out out;
    private final Fragments fragments = new Fragments();
    private final ClientSubscriptions subscriptions;

    /**
     * @param world the world, whose robots the graph publishes
     * @param map the {@code /map} frame (made once per server)
     */
    RosbridgeSession(World world, RosGraph graph, Supplier<String> map, Out out) {
        this.world = world;
        this.graph = graph;
        this.map = map;
        this.out = out;
        this.subscriptions = new ClientSubscriptions(graph, (nanos, publication) -> publish(publication));
    }

    /** Sends what is published and sent up to {@code now}, in order. */
    void advance(long now) {
        subscriptions.advance(now);
    }

    /** When something is next due to be published to the client's subscriptions or sent; {@link Long#MAX_VALUE}: never. */
    long nextDue() {
        return subscriptions.nextDue();
    }

    /** The topics the client holds subscriptions to. */
    int subscriptionCount() {
        return subscriptions.size();
    }

    /** One text message from the client, at {@code now} (after what is due up to then). */
    void request(String text, long now) {
        advance(now);
        JsonNode request;
        Map<String, Object> fields;
        Set<String> integers;
        try {
            request = JsonNode.parse(text, LIMITS);
            if (!request.isObject()) {
                throw request.problem("expected an object, found " + (request.value() == null ? "null" : "another value"));
            }
            @SuppressWarnings("unchecked")
            Map<String, Object> object = (Map<String, Object>) request.value();
            fields = object;
            integers = IntegerFields.of(text);
        } catch (JsonException e) {
            out.log(Level.WARNING, "malformed requests", "malformed JSON: " + e.getMessage());
            return;
        }
        String id = fields.get("id") instanceof String s ? s : null;
        if (!(fields.get("op") instanceof String op)) {
            if (fields.containsKey("op")) {
                out.log(Level.WARNING, "unknown operations", prefix(id) + "Unknown operation: "
                        + shortened(SubscribeRequest.python(fields.get("op"))));
            } else {
                out.log(Level.WARNING, "requests without an op", "Received a message without an op: " + shortened(text));
            }
            return;
        }
        if (!op.equals("subscribe") && !op.equals("unsubscribe") && !op.equals("call_service") && !UNSERVED.contains(op)) {
            out.log(Level.WARNING, "unknown operations", prefix(id) + "Unknown operation: " + shortened(op));
            return;
        }
        if (fields.containsKey("fragment_size")) {
            fragments.set(fields.get("fragment_size"), integers.contains("fragment_size"));
        }
        try {
            switch (op) {
                case "subscribe" -> subscribe(fields, integers, id, now);
                case "unsubscribe" -> unsubscribe(fields, id, now);
                case "call_service" -> callService(request, id);
                default -> out.log(Level.INFO, "unserved operations",
                        prefix(id) + op + " is not served by the world server: it only publishes");
            }
        } catch (JsonException e) {
            out.log(Level.WARNING, "malformed requests", "a request with " + e.getMessage());
        }
    }

    private void subscribe(Map<String, Object> fields, Set<String> integers, String id, long now) {
        SubscribeRequest asked;
        try {
            asked = SubscribeRequest.of(fields, integers);
            if (!subscriptions.subscribe(asked.topic(), asked.id(), asked.throttleMs(), asked.queueLength(), now)) {
                out.log(Level.WARNING, "bad subscriptions", prefix(id) + "subscribe: " + shortened(asked.topic()) + ": already "
                        + ClientSubscriptions.MAX_TOPICS + " topics subscribed to: not subscribed");
                return;
            }
        } catch (SubscribeRequest.Refused | IllegalArgumentException e) {
            out.log(Level.WARNING, "bad subscriptions", prefix(id) + "subscribe: " + shortened(e.getMessage()));
            return;
        }
        String topic = asked.topic();
        String type = asked.type();
        String published = graph.type(topic);
        if (published == null && type == null) {
            out.log(Level.WARNING, "bad subscriptions", prefix(id) + "subscribe: Cannot infer topic type for topic "
                    + shortened(topic) + " as it is not yet advertised");
            return;
        }
        if (published == null) {
            out.log(Level.INFO, "subscriptions to unknown topics", prefix(id) + "subscribe: " + shortened(topic)
                    + " is not published by the world server: nothing will come");
            return;
        }
        if (type != null && !plain(type).equals(published)) {
            out.log(Level.WARNING, "bad subscriptions", prefix(id) + "subscribe: Tried to register topic " + topic
                    + " with type " + shortened(type) + " but it is already established with type " + published);
            return;
        }
        if (!asked.compression().equals("none")) {
            out.log(Level.INFO, "compressions", prefix(id) + "subscribe: compression " + shortened(asked.compression())
                    + " is not served by the world server: JSON text");
        }
        out.log(Level.INFO, "subscriptions", "subscribed to " + topic + " (" + published + ", throttle_rate " + asked.throttleMs()
                + " ms, queue_length " + asked.queueLength() + ")");
        subscriptions.connected(topic, now);
    }

    private void unsubscribe(Map<String, Object> fields, String id, long now) {
        if (!(fields.get("topic") instanceof String topic)) {
            out.log(Level.WARNING, "bad subscriptions", prefix(id) + "unsubscribe: " + (fields.containsKey("topic")
                    ? "Expected field topic to be one of (<class 'str'>,). Invalid value: "
                            + shortened(SubscribeRequest.python(fields.get("topic")))
                    : "Expected a topic field but none was found."));
            return;
        }
        Object sid = fields.get("id");
        try {
            if (!subscriptions.unsubscribe(topic, sid, sid == null, now)) {
                out.log(Level.INFO, "unsubscriptions", prefix(id) + "unsubscribe: not subscribed to " + shortened(topic));
            }
        } catch (IllegalArgumentException e) {
            out.log(Level.WARNING, "bad subscriptions", prefix(id) + "unsubscribe: " + e.getMessage());
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
        send(Json.write(response), id, "the answer to call_service " + shortened(service));
    }

    /** A publication's frame, sent as the connection's fragment_size has it. */
    private void publish(RosGraph.Publication publication) {
        String topic = publication.publisher().topic();
        send(topic.equals(RosGraph.MAP) ? map.get() : RosbridgeMessages.publish(publication, world), null, "a message of " + topic);
    }

    private void send(String frame, Object id, String what) {
        List<String> frames = fragments.of(frame, id);
        if (frames.isEmpty()) {
            out.log(Level.WARNING, "unsendable messages", what + " (" + Fragments.ascii(frame).length() + " chars) is not sent: "
                    + "fragment_size " + shortened(fragments.describe()) + " cannot split it, and rosbridge's send fails");
        }
        frames.forEach(out::send);
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
