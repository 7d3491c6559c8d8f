package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.function.Function;
import java.util.logging.Level;
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

    private final List<String> sent = new ArrayList<>();
    private final List<String> logged = new ArrayList<>();
    private final RosbridgeSession session = new RosbridgeSession(() -> world.at(2), () -> RosbridgeMessages.map(world.at(0).walls(), 0),
            new RosbridgeSession.Out() {
                @Override
                public void send(String frame) {
                    sent.add(frame);
                }

                @Override
                public void log(Level level, String kind, String message) {
                    logged.add(level + " " + message);
                }
            });

    private static String request(String name) throws IOException {
        try (InputStream in = RosbridgeSessionTest.class.getResourceAsStream("/ros/responses/" + name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    @Test
    void badRequestsGetNoAnswerAndOneLineEachAsFromARealRosbridge() throws IOException {
        for (String name : List.of("malformed_json.sent", "missing_op.sent", "nonexistent_type.sent", "unknown_op.sent",
                "unknown_topic_no_type.sent", "unknown_topic_with_type.sent", "wrong_type_existing_topic.sent")) {
            session.request(request(name).strip());
        }
        assertEquals(List.of(), sent, "a real rosbridge answered none of them");
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
        assertEquals(0, session.subscriptionCount());
    }

    @Test
    void aMalformedRequestDoesNotStopTheNext() throws IOException {
        for (String line : request("malformed_then_valid.sent").split("\n")) {
            session.request(line);
        }
        assertEquals(List.of("{\"op\":\"service_response\",\"service\":\"/rosapi/get_time\",\"values\":\"Service /rosapi/get_time"
                + " does not exist\",\"result\":false,\"id\":\"after_bad\"}"), sent);
    }

    @Test
    void aServiceCallIsAnsweredThatTheServiceDoesNotExist() throws Exception {
        session.request(request("call_service_unknown.sent").strip());
        RosFrame answer = RosFrame.parse(sent.get(0), JsonLimits.DEFAULT);
        RosFrame real = RosFrame.parse(request("call_service_unknown.recv.jsonl").strip(), JsonLimits.DEFAULT);
        assertEquals(real.root().value(), answer.root().value(), "the same answer as the real rosbridge's");
    }

    private Map<String, RobotPose> decoded(MessageType type, String frame) throws JsonException {
        return new PoseDecoder(type).decode(frame).stream().collect(Collectors.toMap(RobotPose::name, Function.identity()));
    }

    @Test
    void subscriptionsArePublishedAtTheirTicksAndReadBackByTheDecoders() throws JsonException {
        session.request("{\"op\":\"subscribe\",\"id\":\"s1\",\"topic\":\"/gazebo/model_states\",\"type\":\"gazebo_msgs/ModelStates\","
                + "\"throttle_rate\":200,\"queue_length\":1}");
        session.request("{\"op\":\"subscribe\",\"topic\":\"/tf\",\"type\":\"tf2_msgs/msg/TFMessage\"}");
        session.request("{\"op\":\"subscribe\",\"topic\":\"/Mover/odom\"}");
        assertEquals(3, session.subscriptionCount());
        session.tick(0, world.at(2.5), 2.5);
        assertEquals(3, sent.size());
        Map<String, RobotPose> states = decoded(MessageType.MODEL_STATES, sent.get(0));
        assertEquals(new RobotPose("Scout", 1.25, -3, 0.45, RobotPose.NO_STAMP), states.get("Scout"));
        assertEquals(new RobotPose("Mover", 2.5, 0, 0, RobotPose.NO_STAMP), states.get("Mover"));
        Map<String, RobotPose> tf = decoded(MessageType.TF, sent.get(1));
        assertEquals(new RobotPose("Mover/base_link", 2.5, 0, 0, 2_500_000_000L), tf.get("Mover/base_link"));
        assertEquals(new RobotPose("Mover", 2.5, 0, 0, 2_500_000_000L), decoded(MessageType.ODOMETRY, sent.get(2)).get("Mover"));

        sent.clear();
        session.tick(100_000_000L, world.at(2.6), 2.6);
        assertEquals(2, sent.size(), "model_states waits for its 200 ms");
        session.request("{\"op\":\"unsubscribe\",\"topic\":\"/tf\"}");
        session.request("{\"op\":\"unsubscribe\",\"topic\":\"/Mover/odom\"}");
        sent.clear();
        session.tick(200_000_000L, world.at(2.7), 2.7);
        assertEquals(1, sent.size());
        assertTrue(sent.get(0).startsWith("{\"op\":\"publish\",\"topic\":\"/gazebo/model_states\""));
    }

    @Test
    void theMapIsSentOnSubscribeAndHoldsTheWallsTheWorldCounts() throws JsonException {
        session.request("{\"op\":\"subscribe\",\"topic\":\"/map\",\"type\":\"nav_msgs/OccupancyGrid\"}");
        assertEquals(1, sent.size());
        assertEquals(0, session.subscriptionCount(), "latched: sent once, not at the ticks");
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
