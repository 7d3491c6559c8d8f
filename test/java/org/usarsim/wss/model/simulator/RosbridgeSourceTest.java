package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.net.LogLimiter;

/**
 * The rosbridge source without a socket: the frames a real rosbridge sent (test/resources/ros),
 * handed to it as its WebSocket would, the clock moved by hand.
 */
class RosbridgeSourceTest {

    private static final long MS = TimeUnit.MILLISECONDS.toNanos(1);
    private final ManualClock clock = new ManualClock();
    private final List<LogRecord> log = new ArrayList<>();
    private final Logger logger = Logger.getLogger(RosbridgeSource.class.getName());
    private final Handler handler = new Handler() {
        @Override
        public void publish(LogRecord record) {
            synchronized (log) {
                log.add(record);
            }
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    };
    private LogLimiter limiter;

    @BeforeEach
    void listen() {
        logger.addHandler(handler);
        limiter = new LogLimiter(LogLimiter.FIRST, LogLimiter.ALL_FIRST, LogLimiter.INTERVAL_NS, clock::nanoTime, new LogLimiter.Timer() {
            @Override
            public void after(long delayNs, Runnable task) {
            }

            @Override
            public void stop() {
            }
        });
    }

    @AfterEach
    void stopListening() {
        logger.removeHandler(handler);
    }

    private static List<String> frames(String name) {
        return frames("ros", name);
    }

    /** The frames of a fixture: {@code ros} a real rosbridge 0.11's, {@code ros2} written to rosbridge 2.x's rules. */
    private static List<String> frames(String folder, String name) {
        try (InputStream in = RosbridgeSourceTest.class.getResourceAsStream("/" + folder + "/" + name)) {
            String text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
            return Arrays.stream(text.split("\n")).filter(line -> !line.isEmpty()).toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private RosbridgeSource source(Map<String, String> settings) throws ModelStartException {
        Map<String, String> values = new HashMap<>(settings);
        RosbridgeSource source = new RosbridgeSource(RosbridgeConfig.read(new ModelSettings(values), 200), clock,
                new RosbridgeSource.RunNotes(), limiter);
        source.attach(null); // subscribed, with nothing to send on
        return source;
    }

    private long lines(Level level, String part) {
        synchronized (log) {
            return log.stream().filter(r -> r.getLevel() == level && r.getMessage().contains(part)).count();
        }
    }

    @Test
    void modelStatesListEveryRobotByItsNameAndTheFirstPositionsAreSaidOnce() throws Exception {
        RosbridgeSource source = source(Map.of());
        List<String> frames = frames("model_states.jsonl");
        source.received(frames.get(0));
        Map<String, ReportedRobot> listed = source.positions(List.of());
        assertEquals(List.of("Explorer", "Mapper", "Operator", "Scout"), List.copyOf(listed.keySet()));
        assertEquals(new ReportedRobot("Scout", 43.200443269333334, 0, 0, false), listed.get("Scout"));
        assertEquals(10.0, listed.get("Explorer").x());
        source.received(frames.get(1));
        source.positions(List.of());
        assertEquals(1, lines(Level.INFO, "positions from ws://127.0.0.1:9090 /gazebo/model_states: 4 robots"));
    }

    @Test
    void namesMapWssRobotsToModelsAndOthersAreTheirOwn() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.names", "Alpha=Scout, Bravo = Mapper"));
        source.received(frames("model_states.jsonl").get(0));
        Map<String, ReportedRobot> listed = source.positions(List.of("Alpha"));
        assertEquals(List.of("Alpha", "Bravo", "Explorer", "Operator"), List.copyOf(listed.keySet()),
                "Scout and Mapper are Alpha and Bravo; a model of the name of a renamed robot is none");
        assertEquals(43.200443269333334, listed.get("Alpha").x());
    }

    @Test
    void tfChainsUpToTheFrameByTheirBaseLink() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/tf"));
        List<String> frames = frames("tf.jsonl");
        frames.forEach(source::received);
        Map<String, ReportedRobot> listed = source.positions(List.of());
        assertEquals(List.of("Explorer", "Mapper", "Operator", "Scout"), List.copyOf(listed.keySet()));
        assertEquals(53.333782832, listed.get("Scout").x(), 1e-9);
    }

    @Test
    void odometryOnEachRobotsTopic() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/{robot}/odom"));
        assertNull(source.positions(List.of("Scout")), "subscribed to /Scout/odom, nothing known yet: not nobody");
        source.received(frames("Scout_odom.jsonl").get(0));
        assertEquals(43.200443269333334, source.positions(List.of("Scout")).get("Scout").x());
    }

    @Test
    void aRobotMissingFromTheLatestModelStatesIsUnlistedAtOnce() throws Exception {
        RosbridgeSource source = source(Map.of());
        source.received(frames("model_states.jsonl").get(0));
        source.received(frames("model_states.jsonl").get(1).replace("\"Scout\"", "\"Ghost\""));
        Map<String, ReportedRobot> listed = source.positions(List.of());
        assertTrue(listed.containsKey("Ghost") && !listed.containsKey("Scout"), listed.toString());
    }

    /** A /tf frame: each robot's base_link in world at x, stamped {@code seconds}. */
    private static String tf(double seconds, String... robots) {
        StringBuilder transforms = new StringBuilder();
        for (String robot : robots) {
            transforms.append(transforms.length() == 0 ? "" : ",").append("{\"header\":{\"stamp\":{\"secs\":").append((long) seconds)
                    .append(",\"nsecs\":").append(Math.round((seconds % 1) * 1e9)).append("},\"frame_id\":\"world\"},\"child_frame_id\":\"")
                    .append(robot).append("/base_link\",\"transform\":{\"translation\":{\"x\":1,\"y\":2,\"z\":0},"
                            + "\"rotation\":{\"x\":0,\"y\":0,\"z\":0,\"w\":1}}}");
        }
        return "{\"op\":\"publish\",\"topic\":\"/tf\",\"msg\":{\"transforms\":[" + transforms + "]}}";
    }

    @Test
    void aTfFrameOlderThanTheStaleLimitByItsStampIsUnlistedWhateverTheClock() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/tf", "rosbridge.stale", "1000"));
        source.received(tf(100, "A", "B"));
        source.received(tf(101, "A"));
        assertEquals(List.of("A", "B"), List.copyOf(source.positions(List.of()).keySet()), "B's stamp is 1 s older: at the limit");
        source.received(tf(101.5, "A"));
        assertEquals(List.of("A"), List.copyOf(source.positions(List.of()).keySet()), "B's stamp is 1.5 s older, though it came now");
        source.received(tf(102, "A", "B"));
        assertEquals(List.of("A", "B"), List.copyOf(source.positions(List.of()).keySet()), "B again");
    }

    @Test
    void nothingForTheStaleLimitIsSilenceAndAModelStatesRobotAgesByArrival() throws Exception {
        RosbridgeSource source = source(Map.of()); // 3 poll intervals of 200 ms
        source.received(frames("model_states.jsonl").get(0));
        clock.advance(600 * MS);
        assertEquals(4, source.positions(List.of()).size(), "600 ms: still fresh");
        clock.advance(1 * MS);
        IOException silent = assertThrows(IOException.class, () -> source.positions(List.of()));
        assertEquals("nothing from rosbridge at ws://127.0.0.1:9090 for 601 ms", silent.getMessage());
    }

    @Test
    void aNewWebSocketHasTheGraceForItsFirstMessage() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.grace", "5000"));
        clock.advance(5_000 * MS);
        assertNull(source.positions(List.of()), "nothing yet, not silent yet");
        clock.advance(1 * MS);
        assertEquals("nothing from rosbridge at ws://127.0.0.1:9090 for 5001 ms",
                assertThrows(IOException.class, () -> source.positions(List.of())).getMessage());
    }

    @Test
    void theGraceIsTenSecondsUnlessSetAndNeverBelowFive() throws Exception {
        RosbridgeSource source = source(Map.of());
        clock.advance(10_000 * MS);
        assertNull(source.positions(List.of()), "10 s: not silent yet");
        clock.advance(1 * MS);
        assertThrows(IOException.class, () -> source.positions(List.of()));
        assertTrue(SimulatorSettings.ALL.stream().filter(s -> s.key().equals("rosbridge.grace")).findFirst().orElseThrow()
                .problem("4999") != null, "below 5 s refused");
    }

    @Test
    void theMapsGridComingFirstDoesNotEndTheGraceOfThePoses() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/{robot}/odom", "rosbridge.map", "/map", "rosbridge.grace", "5000"));
        clock.advance(100 * MS);
        source.received(grid());
        clock.advance(4_000 * MS);
        assertNull(source.positions(List.of("Scout")), "4.1 s after the open, the grid alone came: waiting, not silent (issue 31, 4)");
        source.received(frames("Scout_odom.jsonl").get(0));
        assertEquals(List.of("Scout"), List.copyOf(source.positions(List.of("Scout")).keySet()));
    }

    @Test
    void aRobotsOwnTopicIsWaitedForWithinTheGraceThenItsRobotIsUnlisted() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/{robot}/odom", "rosbridge.grace", "5000"));
        List<String> both = List.of("Scout", "Mapper");
        assertNull(source.positions(both));
        String scout = frames("Scout_odom.jsonl").get(0);
        for (int i = 0; i < 50; i++) { // Scout at 10 Hz for 5 s; Mapper's topic never publishes
            clock.advance(100 * MS);
            source.received(scout);
            assertEquals(List.of("Scout"), List.copyOf(source.positions(both).keySet()));
            assertEquals(i < 49 ? Set.of("Mapper") : Set.of(), source.waitedFor(), "at " + (i + 1) * 100 + " ms");
        }
        source.received(scout.replace("Scout", "Mapper"));
        assertEquals(List.of("Mapper", "Scout"), List.copyOf(source.positions(both).keySet()), "its first message lists it");
        assertEquals(Set.of(), source.waitedFor());
    }

    @Test
    void aRobotThatRegistersAgainHasAGraceOfItsOwn() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/{robot}/odom", "rosbridge.grace", "5000"));
        String scout = frames("Scout_odom.jsonl").get(0);
        source.received(scout);
        source.positions(List.of("Scout", "Mapper"));
        clock.advance(6_000 * MS);
        source.received(scout);
        source.positions(List.of("Scout", "Mapper"));
        assertEquals(Set.of(), source.waitedFor(), "Mapper's grace ran out");
        source.positions(List.of("Scout"));
        source.positions(List.of("Scout", "Mapper"));
        assertEquals(Set.of("Mapper"), source.waitedFor(), "Mapper registered again: waited for again");
    }

    @Test
    void aRobotModelStatesListedThenDropsIsNotWaitedFor() throws Exception {
        RosbridgeSource source = source(Map.of());
        List<String> frames = frames("model_states.jsonl");
        source.received(frames.get(0));
        assertEquals(Set.of(), keysOf(source.positions(List.of("Scout")), source.waitedFor(), "Scout"));
        source.received(frames.get(1).replace("\"Scout\"", "\"Ghost\""));
        assertTrue(!source.positions(List.of("Scout")).containsKey("Scout"));
        assertEquals(Set.of(), source.waitedFor(), "listed before, not now: unlisted at once, not waited for");
        source.positions(List.of("Scout", "Late"));
        assertEquals(Set.of("Late"), source.waitedFor(), "a robot Gazebo never listed: waited for");
    }

    private static Set<String> keysOf(Map<String, ReportedRobot> listed, Set<String> waited, String robot) {
        assertTrue(listed.containsKey(robot), listed.toString());
        return waited;
    }

    @Test
    void tfFromSeveralPublishersOneMessagePerRobotListsEveryRobot() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/tf"));
        for (int tick = 0; tick < 10; tick++) {
            for (String robot : List.of("A", "B", "C", "D")) {
                clock.advance(5 * MS);
                source.received(tf(100 + tick * 0.2, robot));
            }
        }
        assertEquals(List.of("A", "B", "C", "D"), List.copyOf(source.positions(List.of("A", "B", "C", "D")).keySet()));
    }

    @Test
    void tfStaticIsComposedWithTf() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/tf", "rosbridge.frame", "map"));
        source.received("{\"op\":\"publish\",\"topic\":\"/tf_static\",\"msg\":{\"transforms\":[{\"header\":{\"stamp\":{\"secs\":1,"
                + "\"nsecs\":0},\"frame_id\":\"map\"},\"child_frame_id\":\"world\",\"transform\":{\"translation\":{\"x\":10,\"y\":0,"
                + "\"z\":0},\"rotation\":{\"x\":0,\"y\":0,\"z\":0,\"w\":1}}}]}}");
        source.received(tf(100, "A"));
        assertEquals(11.0, source.positions(List.of("A")).get("A").x(), 1e-12, "map -> world (static, 10 m) -> A/base_link (1 m)");
    }

    @Test
    void aLatchedTfStaticIsNoSignOfLifeTheGraceGoesOnUntilTfSends() throws Exception {
        // Found against the real rosbridge (RealRosbridgeCheck, scenario 3): tf_static comes at once, the robots' /tf 1.5 s later.
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/tf", "rosbridge.frame", "map", "rosbridge.grace", "5000"));
        source.received(frames("ros2", "tf_static.jsonl").get(0));
        clock.advance(1_500 * MS);
        assertNull(source.positions(List.of("Scout")), "1.5 s after the open, only the latched message: not silent, nothing listed");
        frames("ros2", "tf.jsonl").forEach(source::received);
        assertEquals(0.9, source.positions(List.of("Scout")).get("Scout").x(), 1e-9);
        clock.advance(601 * MS);
        source.received(frames("ros2", "tf_static.jsonl").get(0)); // a reconnection's latched message again
        assertThrows(IOException.class, () -> source.positions(List.of("Scout")), "/tf quiet for the stale limit: silent, whatever tf_static");
    }

    @Test
    void onlyUnreadableMessagesAreSilenceNotEmptinessNobodyUnlisted() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/tf")); // stale 600 ms
        source.received(tf(100, "A", "B"));
        for (int i = 1; i <= 12; i++) {
            clock.advance(50 * MS);
            source.received(tf(100 + i * 0.05, "A").replace("\"x\":1,", "\"x\":NaN,"));
            assertEquals(List.of("A", "B"), List.copyOf(source.positions(List.of("A", "B")).keySet()), "at " + i * 50 + " ms");
        }
        clock.advance(1 * MS);
        assertEquals("nothing readable from rosbridge at ws://127.0.0.1:9090 for 601 ms (12 messages that cannot be read)",
                assertThrows(IOException.class, () -> source.positions(List.of("A", "B"))).getMessage());
    }

    @Test
    void rosbridgeFragmentOpsAreOneMessage() throws Exception {
        RosbridgeSource source = source(Map.of());
        String whole = frames("model_states.jsonl").get(0);
        int size = 300;
        int parts = (whole.length() + size - 1) / size;
        double total = (whole.length() - 1) / (double) size + 1; // as rosbridge 0.11 under Python 3 writes it: not a whole number
        for (int num = 0; num < parts; num++) {
            String data = whole.substring(num * size, Math.min(whole.length(), (num + 1) * size));
            source.received(org.usarsim.wss.ros.Json.write(Map.of("op", "fragment", "id", 0, "data", data, "num", num, "total", total)));
        }
        assertEquals(0, lines(Level.WARNING, ""), log.toString());
        assertEquals(4, source.positions(List.of()).size());
    }

    // ---- ROS 2: rosbridge_suite 2.x's frames (test/resources/ros2/README.md) ----

    @Test
    void ros2TfFromOnePublisherPerRobotComposedWithTfStaticUpToMap() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/tf", "rosbridge.frame", "map", "rosbridge.type", "tf2_msgs/msg/TFMessage"));
        List<String> tf = frames("ros2", "tf.jsonl");
        source.received(tf.get(0));
        assertEquals(Map.of(), source.positions(List.of()), "no chain up to map before /tf_static");
        source.received(frames("ros2", "tf_static.jsonl").get(0));
        tf.forEach(source::received);
        Map<String, ReportedRobot> listed = source.positions(List.of("Scout", "Mapper"));
        assertEquals(List.of("Mapper", "Scout"), List.copyOf(listed.keySet()));
        assertEquals(0.9, listed.get("Scout").x(), 1e-9);
        assertEquals(1.0, listed.get("Scout").y(), 1e-9);
        assertEquals(39.0, listed.get("Mapper").x(), 1e-9, "Mapper/odom at (40, 0) turned 90 degrees: (0.9, 1) there is (39, 0.9)");
        assertEquals(0.9, listed.get("Mapper").y(), 1e-9);
    }

    @Test
    void ros2OdometryOnEachRobotsTopic() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/{robot}/odom", "rosbridge.type", "nav_msgs/msg/Odometry"));
        frames("ros2", "Scout_odom.jsonl").forEach(source::received);
        assertEquals(0.4, source.positions(List.of("Scout")).get("Scout").x(), 1e-9);
    }

    @Test
    void ros2ModelStatesOfGazeboRosState() throws Exception {
        RosbridgeSource source = source(Map.of());
        source.received(frames("ros2", "model_states.jsonl").get(0));
        Map<String, ReportedRobot> listed = source.positions(List.of("Scout", "Mapper"));
        assertEquals(40.0, listed.get("Mapper").x());
        assertEquals(0.05, listed.get("Scout").z());
    }

    @Test
    void gzSimModelPosesBridgedToTfByTheirModelNames() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/tf", "rosbridge.frame", "rescue_world", "rosbridge.names",
                "{robot}={robot}"));
        frames("ros2", "gz_model_pose_tf.jsonl").forEach(source::received);
        Map<String, ReportedRobot> listed = source.positions(List.of("Scout", "Mapper"));
        assertEquals(List.of("Mapper", "Scout"), List.copyOf(listed.keySet()));
        assertEquals(40.04, listed.get("Mapper").x(), 1e-9);
        assertEquals(0.04, listed.get("Scout").x(), 1e-9);
    }

    private static String grid() {
        return "{\"op\":\"publish\",\"topic\":\"/map\",\"msg\":{\"header\":{\"frame_id\":\"world\"},\"info\":{\"resolution\":1.0,"
                + "\"width\":2,\"height\":1,\"origin\":{\"position\":{\"x\":0,\"y\":0,\"z\":0},\"orientation\":{\"x\":0,\"y\":0,\"z\":0,"
                + "\"w\":1}}},\"data\":[0,100]}}";
    }

    @Test
    void aBadFrameIsOneLineAndTheLastGoodPositionsStay() throws Exception {
        RosbridgeSource source = source(Map.of());
        String good = frames("model_states.jsonl").get(0);
        source.received(good);
        source.received(good.substring(0, good.length() / 2));
        source.received("{\"op\":\"publish\",\"topic\":\"/gazebo/model_states\",\"msg\":{\"name\":[\"A\"],\"pose\":null}}");
        source.received("{\"op\":\"publish\",\"topic\":\"/gazebo/model_states\",\"msg\":{\"name\":[\"A\"],\"pose\":[{\"position\":{\"x\":1e999,\"y\":0,\"z\":0}}]}}");
        assertEquals(3, lines(Level.WARNING, "sent a message that cannot be read"), log.toString());
        assertTrue(lines(Level.WARNING, "keeping the last good positions") == 3);
        assertEquals(4, source.positions(List.of()).size());
        for (int i = 0; i < 100; i++) {
            source.received("not json " + i);
        }
        assertEquals(4, lines(Level.WARNING, "sent a message that cannot be read"), "the same problem 100 times: said once");
        for (int i = 0; i < 100; i++) { // "1 poses for N names": a problem of its own each time
            source.received("{\"op\":\"publish\",\"topic\":\"/gazebo/model_states\",\"msg\":{\"name\":["
                    + "\"A\",".repeat(i + 1) + "\"A\"],\"pose\":[{\"position\":{\"x\":0,\"y\":0,\"z\":0}}]}}");
        }
        assertEquals(LogLimiter.ALL_FIRST, lines(Level.WARNING, "sent a message that cannot be read"), "each problem once, limited as warnings are");
    }

    @Test
    void fragmentsAreOneMessageAndOneOverTheLimitIsDropped() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.maxMessage", "1"));
        String frame = frames("model_states.jsonl").get(0);
        int third = frame.length() / 3;
        source.fragment(frame.substring(0, third), false);
        source.fragment(frame.substring(third, 2 * third), false);
        source.fragment(frame.substring(2 * third), true);
        assertEquals(4, source.positions(List.of()).size());

        String big = frame.replace("\"Scout\"", "\"Big\"").replace("\"twist\"", "\"pad\":\"" + "x".repeat(1 << 20) + "\",\"twist\"");
        source.fragment(big.substring(0, 1000), false);
        source.fragment(big.substring(1000), true);
        assertEquals(1, lines(Level.WARNING, "a message longer than 1048576 characters (rosbridge.maxMessage): dropped"));
        assertTrue(source.positions(List.of()).containsKey("Scout"), "the last good positions stay");
        source.fragment(frame.replace("\"Scout\"", "\"After\""), true);
        assertTrue(source.positions(List.of()).containsKey("After"), "the next message is whole again");
    }

    @Test
    void aSubscriptionThatReceivesNothingFor5sIsSaidOnceWithTopicAndType() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.topic", "/tf", "rosbridge.stale", "60000"));
        clock.advance(4_999 * MS);
        source.positions(List.of());
        assertEquals(0, lines(Level.WARNING, "sent nothing on"));
        clock.advance(1 * MS);
        source.positions(List.of());
        clock.advance(1_000 * MS);
        source.positions(List.of());
        assertEquals(1, lines(Level.WARNING, "rosbridge at ws://127.0.0.1:9090 sent nothing on /tf (tf2_msgs/TFMessage) for 5 s"
                + " since it was subscribed: is the topic or its type wrong? (rosbridge answers no error for either)"), log.toString());
    }

    @Test
    void anOccupancyGridGivesTheWallsAndTheCounts() throws Exception {
        RosbridgeSource source = source(Map.of("rosbridge.map", "/map"));
        assertNull(source.walls(), "not known before a grid");
        // 10 x 3 cells of 1 m from (0, 0): column 5 occupied in every row, a wall at x = 5..6.
        StringBuilder data = new StringBuilder();
        for (int row = 0; row < 3; row++) {
            for (int column = 0; column < 10; column++) {
                data.append(data.length() == 0 ? "" : ",").append(column == 5 ? 100 : 0);
            }
        }
        source.received("{\"op\":\"publish\",\"topic\":\"\\/map\",\"msg\":{\"header\":{\"frame_id\":\"world\"},\"info\":{\"resolution\":1.0,"
                + "\"width\":10,\"height\":3,\"origin\":{\"position\":{\"x\":0,\"y\":0,\"z\":0},\"orientation\":{\"x\":0,\"y\":0,\"z\":0,\"w\":1}}},"
                + "\"data\":[" + data + "]}}");
        assertNotNull(source.walls());
        assertEquals(3, source.walls().size(), "one run a row: " + source.walls());
        assertEquals(new org.usarsim.wss.model.Wall(5, 0.5, 6, 0.5), source.walls().get(0));
        source.received("{\"op\":\"publish\",\"topic\":\"/gazebo/model_states\",\"msg\":{\"name\":[\"A\",\"B\",\"C\"],\"pose\":["
                + "{\"position\":{\"x\":1,\"y\":1,\"z\":0}},{\"position\":{\"x\":9,\"y\":1,\"z\":0}},{\"position\":{\"x\":2,\"y\":2,\"z\":0}}]}}");
        source.positions(List.of());
        Map<RobotPair, Double> counts = source.obstacles(List.of(RobotPair.of("A", "B"), RobotPair.of("A", "C"), RobotPair.of("A", "Z")));
        assertEquals(Map.of(RobotPair.of("A", "B"), 1.0, RobotPair.of("A", "C"), 0.0), counts, "none for a robot not listed");
    }

    @Test
    void badSettingsRefuseTheStartNamingTheKey() {
        assertEquals("rosbridge.url: 'http://x' is not a ws:// or wss:// URL with a host",
                assertThrows(ModelStartException.class, () -> source(Map.of("rosbridge.url", "http://x"))).getMessage());
        assertTrue(assertThrows(ModelStartException.class, () -> source(Map.of("rosbridge.topic", "/robots/poses"))).getMessage()
                .startsWith("rosbridge.type: the topic /robots/poses does not tell its type; set rosbridge.type to one of"));
        assertEquals("rosbridge.names: 'Scout' is not WSS=MODEL",
                assertThrows(ModelStartException.class, () -> source(Map.of("rosbridge.names", "Scout"))).getMessage());
        assertEquals("rosbridge.names: two robots are m",
                assertThrows(ModelStartException.class, () -> source(Map.of("rosbridge.names", "A=m,B=m"))).getMessage());
        assertTrue(assertThrows(ModelStartException.class, () -> source(Map.of("rosbridge.topic", "/{robot}/tf", "rosbridge.type",
                "tf2_msgs/TFMessage"))).getMessage().startsWith("rosbridge.topic: /{robot}/tf is one topic per robot"));
    }
}
