package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.OptionalDouble;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.JsonNode;
import org.usarsim.wss.ros.MessageType;
import org.usarsim.wss.ros.PoseDecoder;
import org.usarsim.wss.ros.RobotPose;

/**
 * The rules of rosbridge_suite 0.11.17 (docs/world.md, "Over rosbridge") that the WSS relies on,
 * as the world server's rosbridge side keeps them, without sockets, the world's time moved by the
 * test: several publishers on one topic, the throttle and the queue across them, /tf_static
 * latched, per-robot topics that start after the subscription, fragment_size, and no answer to a
 * bad subscribe. Faults 1 to 3 of issue 31 show here as they did against the real rosbridge.
 */
class RosbridgeRulesTest {

    private static final long MS = 1_000_000L;

    private final World world = new World(List.of(
            new WorldRobot("A", new Point(1, 0, 0), null, OptionalDouble.empty()),
            new WorldRobot("B", new Point(2, 0, 0), null, OptionalDouble.empty())), List.of());
    private final RecordedOut out = new RecordedOut();
    private final List<String> sent = out.sent;
    private final List<String> logged = out.logged;
    private RosbridgeSession session = session(5, 300);

    private RosbridgeSession session(double hz, long delayMs) {
        return new RosbridgeSession(world, new RosGraph(world.robotNames(), hz, delayMs * MS), () -> "{\"op\":\"publish\",\"topic\":\"/map\"}",
                out);
    }

    /** The robots of each /tf message sent, in order: "A", "B". */
    private List<String> tfRobots() throws JsonException {
        List<String> robots = new ArrayList<>();
        for (String frame : sent) {
            if (frame.contains("\"topic\":\"/tf\"")) {
                robots.add(new PoseDecoder(MessageType.TF).decode(frame).stream().map(p -> p.name().replace("/base_link", ""))
                        .collect(Collectors.joining(",")));
            }
        }
        return robots;
    }

    @Test
    void everyTfPublisherIsDeliveredWithThrottle0AndQueue0() throws JsonException {
        session.request("{\"op\":\"subscribe\",\"topic\":\"/tf\",\"type\":\"tf2_msgs/TFMessage\",\"throttle_rate\":0,\"queue_length\":0}",
                0);
        session.advance(1000 * MS);
        assertEquals(List.of("B", "A", "B", "A", "B", "A", "B", "A", "B", "A"), tfRobots(),
                "5 Hz, one message per robot each, A at 0, B half a period later: B at 0.1 s first");
    }

    @Test
    void throttle200Queue1PassesOneTfPublisherAlone() throws JsonException {
        // issue 31, fault 2: the WSS's old subscription options
        session.request("{\"op\":\"subscribe\",\"topic\":\"/tf\",\"throttle_rate\":200,\"queue_length\":1}", 0);
        session.advance(5000 * MS);
        List<String> robots = tfRobots();
        assertEquals(25, robots.size());
        assertEquals("B", robots.get(0), "the first at once");
        assertEquals(List.of("A"), robots.subList(1, 25).stream().distinct().toList(),
                "then A's alone, each sent at the last send + 200 ms, as B's comes (after it): " + robots);
    }

    @Test
    void throttle200Queue1HoldsEachMessageUntilTheLastSendPlus200() throws JsonException {
        // issue 31, fault 3: at 20 Hz a message waits for the next send
        session = session(20, 0);
        session.request("{\"op\":\"subscribe\",\"topic\":\"/A/odom\",\"throttle_rate\":200,\"queue_length\":1}", 1 * MS);
        assertEquals(List.of("50@50", "200@250", "400@450"), stampsSentAt(1, 460), "published@sent, in ms");
        session.request("{\"op\":\"unsubscribe\",\"topic\":\"/A/odom\"}", 460 * MS);
        session.request("{\"op\":\"subscribe\",\"topic\":\"/A/odom\"}", 460 * MS);
        assertEquals(List.of("500@500", "550@550", "600@600"), stampsSentAt(460, 600), "throttle 0: as they are published");
    }

    /** The stamps of the odometry sent as the time goes from one ms to the other, each with the ms it was sent at. */
    private List<String> stampsSentAt(long fromMs, long toMs) throws JsonException {
        List<String> stamps = new ArrayList<>();
        for (long ms = fromMs; ms <= toMs; ms++) {
            sent.clear();
            session.advance(ms * MS);
            for (String frame : sent) {
                stamps.add(new PoseDecoder(MessageType.ODOMETRY).decode(frame).get(0).stampNanos() / MS + "@" + ms);
            }
        }
        return stamps;
    }

    @Test
    void tfStaticIsLatchedToEachSubscriptionAndEachSubscribeDeliversItAgain() throws JsonException {
        session.request("{\"op\":\"subscribe\",\"id\":\"a\",\"topic\":\"/tf_static\"}", 7000 * MS);
        assertEquals(1, sent.size(), "at once, though published at 0");
        JsonNode transform = JsonNode.parse(sent.get(0), JsonLimits.DEFAULT).get("msg").get("transforms").items().get(0);
        assertEquals("map", transform.get("header").get("frame_id").string());
        assertEquals("world", transform.get("child_frame_id").string());
        assertEquals(0.0, transform.get("header").get("stamp").get("secs").number());
        session.advance(60_000 * MS);
        assertEquals(1, sent.size(), "sent once");
        session.request("{\"op\":\"subscribe\",\"id\":\"a\",\"topic\":\"/tf_static\"}", 60_000 * MS);
        session.request("{\"op\":\"subscribe\",\"id\":\"b\",\"topic\":\"/tf_static\",\"throttle_rate\":1000}", 60_100 * MS);
        assertEquals(3, sent.size(), "each subscribe op delivers it again, through the handler");
        session.request("{\"op\":\"subscribe\",\"id\":\"b\",\"topic\":\"/tf_static\",\"throttle_rate\":1000}", 60_200 * MS);
        assertEquals(4, sent.size(), "the same id again too");
        session.request("{\"op\":\"unsubscribe\",\"id\":\"a\",\"topic\":\"/tf_static\"}", 60_300 * MS);
        session.request("{\"op\":\"subscribe\",\"id\":\"b\",\"topic\":\"/tf_static\",\"throttle_rate\":1000}", 60_400 * MS);
        assertEquals(4, sent.size(), "b's throttle of 1000 ms alone since 60.3 s: dropped within a second of the last send (60.2 s)");
    }

    @Test
    void aPerRobotTopicStartsOnlyAfterTheConnectionDelay() throws JsonException {
        session.request("{\"op\":\"subscribe\",\"topic\":\"/B/odom\",\"type\":\"nav_msgs/Odometry\"}", 1000 * MS);
        assertEquals(1500 * MS, session.nextDue(), "B's at phase 100 ms of 200: 1.1 and 1.3 s are not after the 300 ms, 1.5 s is");
        session.advance(1500 * MS);
        RobotPose first = new PoseDecoder(MessageType.ODOMETRY).decode(sent.get(0)).get(0);
        assertEquals(1_500_000_000L, first.stampNanos());
        session = session(5, 0);
        sent.clear();
        session.request("{\"op\":\"subscribe\",\"topic\":\"/B/odom\"}", 1000 * MS);
        session.advance(1100 * MS);
        assertEquals(1_100_000_000L, new PoseDecoder(MessageType.ODOMETRY).decode(sent.get(0)).get(0).stampNanos(),
                "no delay: the next publication");
    }

    @Test
    void fragmentSizeIsTheConnectionsFromAnyKnownOpOn() throws JsonException {
        session.request("{\"op\":\"frobnicate\",\"fragment_size\":10}", 0);
        session.request("{\"op\":\"subscribe\",\"topic\":\"/tf_static\"}", 0);
        assertEquals(1, sent.size(), "an unknown op sets nothing");
        session.request("{\"op\":\"subscribe\",\"topic\":\"/nowhere\",\"fragment_size\":100}", 0);
        session.request("{\"op\":\"subscribe\",\"topic\":\"/tf_static\"}", 0);
        assertTrue(sent.size() > 3, "a subscribe that fails sets it too, for every later frame");
        StringBuilder whole = new StringBuilder();
        for (String fragment : sent.subList(1, sent.size())) {
            JsonNode op = JsonNode.parse(fragment, JsonLimits.DEFAULT);
            assertEquals("fragment", op.get("op").string());
            assertEquals(0.0, op.get("id").number());
            whole.append(op.get("data").string());
        }
        assertEquals(sent.get(0), whole.toString(), "the publish frame, reassembled");
        sent.clear();
        session.request("{\"op\":\"call_service\",\"service\":\"/x\",\"fragment_size\":null}", 0);
        session.request("{\"op\":\"subscribe\",\"topic\":\"/tf_static\"}", 0);
        assertEquals(2, sent.size(), "null: whole again");
        sent.clear();
        logged.clear();
        session.request("{\"op\":\"subscribe\",\"topic\":\"/tf_static\",\"fragment_size\":100.0}", 0);
        assertEquals(List.of(), sent);
        assertTrue(logged.get(0).startsWith("WARNING subscribe: Expected field fragment_size to be one of (<class 'int'>,). Invalid value: "
                + "100.0"), logged.toString());
        session.request("{\"op\":\"subscribe\",\"topic\":\"/tf_static\"}", 0);
        assertEquals(List.of(), sent, "100.0 is the connection's now: rosbridge's send fails on every longer frame");
        assertTrue(logged.get(logged.size() - 1).startsWith("WARNING a message of /tf_static ("), logged.toString());
    }

    @Test
    void aBadSubscribeGetsNoAnswerAndOneLine() {
        for (String request : List.of(
                "{\"op\":\"subscribe\",\"id\":\"t\",\"topic\":\"/tf\",\"throttle_rate\":100.0}",
                "{\"op\":\"subscribe\",\"id\":\"q\",\"topic\":\"/tf\",\"queue_length\":\"1\"}",
                "{\"op\":\"subscribe\",\"id\":\"f\",\"topic\":\"/tf\",\"fragment_size\":1.5}",
                "{\"op\":\"subscribe\",\"id\":\"n\",\"type\":\"tf2_msgs/TFMessage\"}",
                "{\"op\":\"subscribe\",\"id\":\"y\",\"topic\":\"/tf\",\"type\":null}",
                "{\"op\":\"subscribe\",\"id\":{\"a\":1},\"topic\":\"/tf\"}",
                "{\"op\":\"subscribe\",\"id\":\"m\",\"topic\":\"/tf\",\"queue_length\":-1}")) {
            session.request(request, 0);
        }
        session.advance(10_000 * MS);
        assertEquals(List.of(), sent);
        assertEquals(List.of(
                "WARNING [id: t] subscribe: Expected field throttle_rate to be one of (<class 'int'>,). Invalid value: 100.0",
                "WARNING [id: q] subscribe: Expected field queue_length to be one of (<class 'int'>,). Invalid value: 1",
                "WARNING [id: f] subscribe: Expected field fragment_size to be one of (<class 'int'>,). Invalid value: 1.5",
                "WARNING [id: n] subscribe: Expected a topic field but none was found.",
                "WARNING [id: y] subscribe: Expected field type to be one of (<class 'str'>,). Invalid value: None",
                "WARNING subscribe: unhashable type: 'dict'",
                "WARNING [id: m] subscribe: maxlen must be non-negative"), logged);
    }

    @Test
    void aFailedSubscribesParametersStayAndCombineWithALaterOne() {
        session.request("{\"op\":\"subscribe\",\"id\":\"bad\",\"topic\":\"/gazebo/model_states\",\"type\":\"nav_msgs/Odometry\","
                + "\"throttle_rate\":1000}", 0);
        session.advance(1000 * MS);
        assertEquals(List.of(), sent, "failed: nothing comes");
        session.request("{\"op\":\"subscribe\",\"id\":\"good\",\"topic\":\"/gazebo/model_states\",\"throttle_rate\":300,"
                + "\"queue_length\":1}", 1100 * MS);
        session.advance(3000 * MS);
        assertEquals(5, sent.size(), "throttle min(1000, 300), queue min(0, 1): 0, so drop mode, 1.2, 1.6, 2.0, 2.4, 2.8 s");
        sent.clear();
        session = session(5, 300);
        session.request("{\"op\":\"subscribe\",\"id\":\"good\",\"topic\":\"/gazebo/model_states\",\"throttle_rate\":300,"
                + "\"queue_length\":1}", 1100 * MS);
        session.advance(3000 * MS);
        assertEquals(7, sent.size(), "alone: queue 1, every 300 ms from 1.2 s to 3.0 s");
    }

    @Test
    void aThreadHeldUpCatchesUpTenSecondsAtMost() {
        session.request("{\"op\":\"subscribe\",\"topic\":\"/gazebo/model_states\"}", 0);
        session.advance(60_000 * MS);
        assertEquals(50, sent.size(), "5 Hz, the last 10 s");
    }
}
