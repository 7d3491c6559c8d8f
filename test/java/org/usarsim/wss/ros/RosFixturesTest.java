package org.usarsim.wss.ros;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * Every frame a real rosbridge sent, parsed exactly as it came ({@code \/} escapes and all), and
 * the poses checked against the motions its README describes: Scout drives x 0 -> 80 -> 0 m over
 * 60 s on y = 0; Operator circles (20, 20) at radius 10 m every 120 s; Explorer x = 10, y 0 -> 40
 * -> 0 over 80 s; Mapper drives the square (40,0) (70,0) (70,30) (40,30) at 1 m/s.
 */
class RosFixturesTest {

    private static final double EPSILON = 1e-6;

    /** Each frame's poses by name, decoded by one decoder of the type (tf keeps its tree). */
    private static List<Map<String, RobotPose>> decoded(String fixture, MessageType type) throws JsonException {
        PoseDecoder decoder = new PoseDecoder(type);
        List<Map<String, RobotPose>> frames = new ArrayList<>();
        for (String frame : RosFixtures.frames(fixture)) {
            frames.add(decoder.decode(frame).stream().collect(Collectors.toMap(RobotPose::name, Function.identity())));
        }
        return frames;
    }

    @Test
    void theFramesHoldEscapedSlashesAsSent() {
        assertTrue(RosFixtures.frames(RosFixtures.TF).get(0).startsWith("{\"op\":\"publish\",\"topic\":\"\\/tf\""));
        assertEquals(20, RosFixtures.frames(RosFixtures.TF).size());
        assertEquals(20, RosFixtures.frames(RosFixtures.MODEL_STATES).size());
        assertEquals(20, RosFixtures.frames(RosFixtures.SCOUT_ODOM).size());
    }

    @Test
    void everyFrameParsesWithItsTopicUnescaped() throws JsonException {
        Map<String, String> topics = Map.of(RosFixtures.TF, "/tf", RosFixtures.MODEL_STATES, "/gazebo/model_states",
                RosFixtures.SCOUT_ODOM, "/Scout/odom");
        for (Map.Entry<String, String> fixture : topics.entrySet()) {
            for (String text : RosFixtures.frames(fixture.getKey())) {
                RosFrame frame = RosFrame.parse(text, JsonLimits.DEFAULT);
                assertTrue(frame.isPublish());
                assertEquals(fixture.getValue(), frame.topic());
                assertEquals(MessageType.ofTopic(frame.topic()).orElseThrow(),
                        Map.of("/tf", MessageType.TF, "/gazebo/model_states", MessageType.MODEL_STATES,
                                "/Scout/odom", MessageType.ODOMETRY).get(frame.topic()));
            }
        }
    }

    @Test
    void modelStatesGiveTheFourRobotsWithoutAStamp() throws JsonException {
        for (Map<String, RobotPose> frame : decoded(RosFixtures.MODEL_STATES, MessageType.MODEL_STATES)) {
            assertEquals(List.of("Explorer", "Mapper", "Operator", "Scout"), frame.keySet().stream().sorted().toList());
            frame.values().forEach(pose -> assertEquals(RobotPose.NO_STAMP, pose.stampNanos()));
            frame.values().forEach(pose -> assertEquals(0.0, pose.z()));
        }
    }

    @Test
    void tfGivesEachBaseLinkInTheWorldFrameWithItsStamp() throws JsonException {
        List<Map<String, RobotPose>> tf = decoded(RosFixtures.TF, MessageType.TF);
        List<Map<String, RobotPose>> states = decoded(RosFixtures.MODEL_STATES, MessageType.MODEL_STATES);
        assertEquals(1795735210_420317173L, tf.get(0).get("Scout/base_link").stampNanos());
        for (int i = 0; i < tf.size(); i++) {
            assertEquals(4, tf.get(i).size());
            for (RobotPose state : states.get(i).values()) {
                RobotPose fromTf = tf.get(i).get(state.name() + "/base_link");
                assertEquals(state.x(), fromTf.x(), EPSILON, state.name());
                assertEquals(state.y(), fromTf.y(), EPSILON, state.name());
            }
        }
    }

    @Test
    void scoutsOdometryIsScoutsModelState() throws JsonException {
        List<Map<String, RobotPose>> odom = decoded(RosFixtures.SCOUT_ODOM, MessageType.ODOMETRY);
        List<Map<String, RobotPose>> tf = decoded(RosFixtures.TF, MessageType.TF);
        for (int i = 0; i < odom.size(); i++) {
            RobotPose scout = odom.get(i).get("Scout");
            assertEquals(tf.get(i).get("Scout/base_link").x(), scout.x(), EPSILON);
            assertEquals(tf.get(i).get("Scout/base_link").stampNanos(), scout.stampNanos());
        }
    }

    @Test
    void theRobotsMoveAsTheReadmeSays() throws JsonException {
        List<Map<String, RobotPose>> tf = decoded(RosFixtures.TF, MessageType.TF);
        Map<String, RobotPose> last = new HashMap<>();
        for (Map<String, RobotPose> frame : tf) {
            RobotPose scout = frame.get("Scout/base_link");
            RobotPose operator = frame.get("Operator/base_link");
            RobotPose explorer = frame.get("Explorer/base_link");
            RobotPose mapper = frame.get("Mapper/base_link");
            assertEquals(0, scout.y(), EPSILON);
            assertTrue(scout.x() >= 0 && scout.x() <= 80);
            assertEquals(10, Math.hypot(operator.x() - 20, operator.y() - 20), EPSILON);
            assertEquals(10, explorer.x(), EPSILON);
            assertTrue(explorer.y() >= 0 && explorer.y() <= 40);
            assertTrue(onTheSquare(mapper), mapper.toString());
            if (!last.isEmpty()) {
                double dt = (scout.stampNanos() - last.get("Scout/base_link").stampNanos()) / 1e9;
                assertEquals(80.0 / 30 * dt, Math.abs(scout.x() - last.get("Scout/base_link").x()), 1e-3);
                assertEquals(1.0 * dt, Math.abs(explorer.y() - last.get("Explorer/base_link").y()), 1e-3);
                assertEquals(1.0 * dt, Math.hypot(mapper.x() - last.get("Mapper/base_link").x(),
                        mapper.y() - last.get("Mapper/base_link").y()), 1e-3);
                RobotPose before = last.get("Operator/base_link");
                double chord = 2 * 10 * Math.sin(Math.PI / 120 * dt);
                assertEquals(chord, Math.hypot(operator.x() - before.x(), operator.y() - before.y()), 1e-3);
            }
            last = frame;
        }
    }

    private static boolean onTheSquare(RobotPose p) {
        boolean alongX = p.x() >= 40 - EPSILON && p.x() <= 70 + EPSILON
                && (Math.abs(p.y()) < EPSILON || Math.abs(p.y() - 30) < EPSILON);
        boolean alongY = p.y() >= -EPSILON && p.y() <= 30 + EPSILON
                && (Math.abs(p.x() - 40) < EPSILON || Math.abs(p.x() - 70) < EPSILON);
        return alongX || alongY;
    }

    @Test
    void theServersAnswersAreFramesWithoutPoses() throws JsonException {
        PoseDecoder decoder = new PoseDecoder(MessageType.MODEL_STATES);
        List<String> answers = RosFixtures.all().stream().filter(frame -> !frame.contains("\"op\":\"publish\"")).toList();
        assertEquals(4, answers.size());
        for (String answer : answers) {
            RosFrame frame = RosFrame.parse(answer, JsonLimits.DEFAULT);
            assertEquals("service_response", frame.op());
            assertEquals(List.of(), decoder.decode(frame));
        }
        RosFrame topics = RosFrame.parse(RosFixtures.frames("responses/call_service_rosapi_topics.recv.jsonl").get(0),
                JsonLimits.DEFAULT);
        assertEquals("/gazebo/model_states", topics.root().get("values").get("topics").items().get(6).string());
    }
}
