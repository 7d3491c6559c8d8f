package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.MessageType;
import org.usarsim.wss.ros.OccupancyGrid;
import org.usarsim.wss.ros.PoseDecoder;
import org.usarsim.wss.ros.RobotPose;
import org.usarsim.wss.ros.RosFrame;

/**
 * A rosbridge client's requests as the world server takes them, without sockets: the requests a
 * real rosbridge was sent (test/resources/ros/responses/*.sent) get what it answered, and the
 * messages published are read back by the position sources' own decoders.
 */
class RosbridgeSessionTest {

    private final World world = new World(List.of(
            new WorldRobot("Scout", new Point(1.25, -3, 0.45), null, OptionalDouble.empty()),
            new WorldRobot("Mover", new Point(0, 0, 0), new Route(new Point(0, 0, 0), List.of(new Point(10, 0, 0)), 1, false),
                    OptionalDouble.empty())),
            List.of(new Wall(5, -10, 5, 10), new Wall(7, -10, 7, 10), new Wall(-1, 1, 1, 1)));

    private static final long MS = 1_000_000L;
    /** The session's time: 2 s into the world (publishers at 20 Hz, as the server's default). */
    private static final long NOW = 2000 * MS;

    private final RecordedOut out = new RecordedOut();
    private final List<String> sent = out.sent;
    private final List<String> logged = out.logged;
    private final RosbridgeSession session = new RosbridgeSession(world, new RosGraph(world.robotNames(), 20, 300 * MS),
            () -> RosbridgeMessages.map(world.walls(), 0), out);

    private static String request(String name) throws IOException {
        try (InputStream in = RosbridgeSessionTest.class.getResourceAsStream("/ros/responses/" + name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    @Test
    void badRequestsGetNoAnswerAndOneLineEachAsFromARealRosbridge() throws IOException {
        for (String name : List.of("malformed_json.sent", "missing_op.sent", "nonexistent_type.sent", "unknown_op.sent",
                "unknown_topic_no_type.sent", "unknown_topic_with_type.sent", "wrong_type_existing_topic.sent")) {
            session.request(request(name).strip(), NOW);
        }
        session.advance(NOW + 1000 * MS);
        assertEquals(List.of(), sent, "a real rosbridge answered none of them, nor sends anything after");
        assertEquals(List.of(
                "WARNING malformed JSON: at offset 32: the text ends where a key in quotes was expected (truncated)",
                "WARNING Received a message without an op: {\"topic\":\"/tf\"}",
                "WARNING [id: w2] subscribe: Tried to register topic /Scout/odom with type foo_msgs/Bar but it is already"
                        + " established with type nav_msgs/Odometry",
                "WARNING [id: x1] Unknown operation: frobnicate",
                "WARNING [id: u1] subscribe: Cannot infer topic type for topic /no_such_topic as it is not yet advertised",
                "INFO [id: u2] subscribe: /no_such_topic is not published by the world server: nothing will come",
                "WARNING [id: w1] subscribe: Tried to register topic /tf with type nav_msgs/Odometry but it is already"
                        + " established with type tf2_msgs/TFMessage"), logged);
        assertEquals(3, session.subscriptionCount(), "rosbridge keeps a subscription made by an op that then failed: /Scout/odom,"
                + " /tf, /no_such_topic");
    }

    @Test
    void aMalformedRequestDoesNotStopTheNext() throws IOException {
        for (String line : request("malformed_then_valid.sent").split("\n")) {
            session.request(line, NOW);
        }
        assertEquals(List.of("{\"op\":\"service_response\",\"service\":\"/rosapi/get_time\",\"values\":\"Service /rosapi/get_time"
                + " does not exist\",\"result\":false,\"id\":\"after_bad\"}"), sent);
    }

    @Test
    void aServiceCallIsAnsweredThatTheServiceDoesNotExist() throws Exception {
        session.request(request("call_service_unknown.sent").strip(), NOW);
        RosFrame answer = RosFrame.parse(sent.get(0), JsonLimits.DEFAULT);
        RosFrame real = RosFrame.parse(request("call_service_unknown.recv.jsonl").strip(), JsonLimits.DEFAULT);
        assertEquals(real.root().value(), answer.root().value(), "the same answer as the real rosbridge's");
    }

    private Map<String, RobotPose> decoded(MessageType type, String frame) throws JsonException {
        return new PoseDecoder(type).decode(frame).stream().collect(Collectors.toMap(RobotPose::name, Function.identity()));
    }

    @Test
    void subscriptionsArePublishedAsTheGraphPublishesAndReadBackByTheDecoders() throws JsonException {
        session.request("{\"op\":\"subscribe\",\"id\":\"s1\",\"topic\":\"/gazebo/model_states\",\"type\":\"gazebo_msgs/ModelStates\","
                + "\"throttle_rate\":200,\"queue_length\":1}", 2490 * MS);
        session.request("{\"op\":\"subscribe\",\"topic\":\"/tf\",\"type\":\"tf2_msgs/msg/TFMessage\"}", 2490 * MS);
        session.request("{\"op\":\"subscribe\",\"topic\":\"/Mover/odom\"}", 2490 * MS);
        assertEquals(3, session.subscriptionCount());
        assertEquals(2500 * MS, session.nextDue(), "model_states and Scout's /tf at 2.5 s");
        session.advance(2500 * MS);
        assertEquals(2, sent.size());
        Map<String, RobotPose> states = decoded(MessageType.MODEL_STATES, sent.get(0));
        assertEquals(new RobotPose("Scout", 1.25, -3, 0.45, RobotPose.NO_STAMP), states.get("Scout"));
        assertEquals(new RobotPose("Mover", 2.5, 0, 0, RobotPose.NO_STAMP), states.get("Mover"));
        assertEquals(Map.of("Scout/base_link", new RobotPose("Scout/base_link", 1.25, -3, 0.45, 2_500_000_000L)),
                decoded(MessageType.TF, sent.get(1)), "Scout's own publisher: its transform alone");
        session.advance(2525 * MS);
        RobotPose mover = decoded(MessageType.TF, sent.get(2)).get("Mover/base_link");
        assertEquals(2_525_000_000L, mover.stampNanos(), "Mover's own publisher, half a period later");
        assertEquals(2.525, mover.x(), 1e-9);
        assertTrue(sent.stream().noneMatch(frame -> frame.contains("/Mover/odom")));
        session.advance(2850 * MS);
        RobotPose odometry = decoded(MessageType.ODOMETRY, sent.stream().filter(frame -> frame.contains("/Mover/odom")).findFirst()
                .orElseThrow()).get("Mover");
        assertEquals(2_825_000_000L, odometry.stampNanos(), "the first odometry after the connection delay (300 ms after 2.49 s)");
        assertEquals(2.825, odometry.x(), 1e-9);

        session.request("{\"op\":\"unsubscribe\",\"topic\":\"/tf\"}", 2850 * MS);
        session.request("{\"op\":\"unsubscribe\",\"topic\":\"/Mover/odom\"}", 2850 * MS);
        sent.clear();
        session.advance(3000 * MS);
        assertEquals(1, sent.size(), "model_states at most once in 200 ms: " + sent);
        assertTrue(sent.get(0).startsWith("{\"op\":\"publish\",\"topic\":\"/gazebo/model_states\""));
        assertEquals(2.85, decoded(MessageType.MODEL_STATES, sent.get(0)).get("Mover").x(), 1e-9,
                "sent at 2.9 s (the last send, 2.7 s, + 200 ms), the newest published before it: its queue of 1 held 2.85 s's");
    }

    @Test
    void theMapIsSentOnSubscribeAndHoldsTheWallsTheWorldCounts() throws JsonException {
        session.request("{\"op\":\"subscribe\",\"topic\":\"/map\",\"type\":\"nav_msgs/OccupancyGrid\"}", NOW);
        session.advance(NOW + 5000 * MS);
        assertEquals(1, sent.size(), "latched: sent once, on subscribe");
        OccupancyGrid grid = OccupancyGrid.of(RosFrame.parse(sent.get(0), JsonLimits.DEFAULT).msg());
        assertEquals(RosbridgeMessages.RESOLUTION, grid.resolution(), 1e-12);
        assertEquals("world", grid.frameId());
        Snapshot at = world.at(0);
        double[][] from = {{0, 0}, {1.25, -3}, {6, 5}, {0, 2}, {9, -9}};
        for (double[] a : from) {
            for (double[] b : from) {
                int walls = (int) at.walls().stream().filter(wall -> wall.blocks(new Point(a[0], a[1], 0), new Point(b[0], b[1], 0)))
                        .count();
                assertEquals(walls, grid.crossings(a[0], a[1], b[0], b[1]), () -> java.util.Arrays.toString(a) + " to "
                        + java.util.Arrays.toString(b));
            }
        }
    }

    @Test
    void aWorldTooLargeForFourMillionCellsGetsCoarserCells() throws JsonException {
        String frame = RosbridgeMessages.map(List.of(new Wall(0, 0, 1000, 0), new Wall(0, 0, 0, 1000)), 0);
        OccupancyGrid grid = OccupancyGrid.of(RosFrame.parse(frame, JsonLimits.DEFAULT).msg());
        assertEquals(0.8, grid.resolution(), 1e-12);
        assertTrue((long) grid.width() * grid.height() <= RosbridgeMessages.MAX_CELLS);
        assertEquals(1, grid.crossings(500, -5, 500, 5));
    }
}
