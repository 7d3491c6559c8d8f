package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.time.Duration;
import java.util.HashSet;
import java.util.List;
import java.util.OptionalDouble;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.JsonNode;
import org.usarsim.wss.ros.MessageType;
import org.usarsim.wss.ros.PoseDecoder;
import org.usarsim.wss.ros.RobotPose;

/**
 * rosbridge_suite's rules the WSS relies on, over real WebSockets on 127.0.0.1 against the world
 * server's rosbridge, its world running in real time, three robots published at 20 Hz: several
 * /tf publishers, /tf_static latched, per-robot odometry after the connection delay, fragment
 * ops, no answer to a bad subscribe. Slow: it waits for the publishers in real time. Times are
 * checked by the messages' stamps (the world's time), never by the wall clock.
 */
@Tag("slow")
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RosbridgeSocketRulesTest {

    private static final List<String> ROBOTS = List.of("A", "B", "C");
    private static final double RATE_HZ = 20;

    private final World world = new World(ROBOTS.stream().map(name -> new WorldRobot(name, new Point(ROBOTS.indexOf(name), 0, 0), null,
            OptionalDouble.empty())).toList(), List.of());
    private final long started = System.nanoTime();
    private RunningRosbridge running;

    @BeforeEach
    void start() throws IOException {
        running = new RunningRosbridge(world, () -> (System.nanoTime() - started) / 1e9, RATE_HZ, Duration.ofMillis(300));
    }

    @AfterEach
    void stop() {
        running.close();
    }

    private ReceivedFrames client(String... requests) {
        ReceivedFrames received = new ReceivedFrames();
        running.connect(received, requests);
        return received;
    }

    private static RobotPose onlyPose(MessageType type, String frame) throws JsonException {
        List<RobotPose> poses = new PoseDecoder(type).decode(frame);
        assertEquals(1, poses.size(), frame);
        return poses.get(0);
    }

    private static long nanos(double seconds) {
        return Math.round(seconds * 1e9);
    }

    @Test
    void everyTfPublisherIsDeliveredWithThrottle0AndQueue0AtItsOwnPhase() throws Exception {
        ReceivedFrames received = client("{\"op\":\"subscribe\",\"topic\":\"/tf\",\"throttle_rate\":0,\"queue_length\":0}");
        Set<String> seen = new HashSet<>();
        for (int i = 0; i < 6; i++) {
            RobotPose pose = onlyPose(MessageType.TF, received.next());
            String robot = pose.name().replace("/base_link", "");
            seen.add(robot);
            double publishedAt = RosbridgeServer.firstPublishAtOrAfter("/tf", robot, ROBOTS, RATE_HZ, (pose.stampNanos() - 1) / 1e9);
            assertEquals(pose.stampNanos(), nanos(publishedAt), robot + "'s own publisher, at its phase");
        }
        assertEquals(Set.copyOf(ROBOTS), seen, "each robot's transform, from its own publisher");
    }

    @Test
    void throttle200Queue1PassesOneTfPublisherAlone() throws Exception {
        ReceivedFrames received = client("{\"op\":\"subscribe\",\"topic\":\"/tf\",\"throttle_rate\":200,\"queue_length\":1}");
        received.next();
        Set<String> robots = new HashSet<>();
        for (int i = 0; i < 5; i++) {
            robots.add(onlyPose(MessageType.TF, received.next()).name());
        }
        assertEquals(1, robots.size(), "after the first, the publisher whose message is newest at each send alone: " + robots);
    }

    @Test
    void tfStaticIsLatchedToEachNewSubscriptionAndEachSubscribeDeliversItAgain() throws Exception {
        String subscribe = "{\"op\":\"subscribe\",\"id\":\"s\",\"topic\":\"/tf_static\"}";
        ReceivedFrames first = client(subscribe);
        ReceivedFrames second = client(subscribe, subscribe);
        for (ReceivedFrames received : List.of(first, second, second)) {
            JsonNode transform = JsonNode.parse(received.next(), JsonLimits.DEFAULT).get("msg").get("transforms").items().get(0);
            assertEquals("map", transform.get("header").get("frame_id").string());
            assertEquals("world", transform.get("child_frame_id").string());
        }
        assertTrue(first.texts.isEmpty() && second.texts.isEmpty(), "once per subscribe op");
    }

    @Test
    void aPerRobotTopicsFirstMessageComesNoEarlierThanTheConnectionDelayAfterTheSubscribe() throws Exception {
        double before = running.world.time();
        ReceivedFrames received = client("{\"op\":\"subscribe\",\"topic\":\"/B/odom\",\"type\":\"nav_msgs/Odometry\"}");
        RobotPose first = onlyPose(MessageType.ODOMETRY, received.next());
        assertEquals("B", first.name());
        assertTrue(first.stampNanos() > nanos(before + 0.3), "published " + first.stampNanos() / 1e9 + " s, subscribed after "
                + before + " s");
        RobotPose second = onlyPose(MessageType.ODOMETRY, received.next());
        assertEquals(nanos(1 / RATE_HZ), second.stampNanos() - first.stampNanos(), "then at the publisher's rate");
    }

    @Test
    void aFrameLongerThanFragmentSizeComesInFragmentOpsThatMakeItUp() throws Exception {
        ReceivedFrames received = client("{\"op\":\"subscribe\",\"topic\":\"/gazebo/model_states\",\"fragment_size\":100}");
        JsonNode fragment = JsonNode.parse(received.next(), JsonLimits.DEFAULT);
        assertEquals("fragment", fragment.get("op").string());
        while (fragment.get("num").number() != 0) {
            fragment = JsonNode.parse(received.next(), JsonLimits.DEFAULT);
        }
        StringBuilder frame = new StringBuilder(fragment.get("data").string());
        double total = fragment.get("total").number();
        // as many as Python 3's total truncated: (len - 1) / size + 1 is 6.99 for 600 chars in 6 fragments of 100
        for (int num = 1; num < (int) total; num++) {
            fragment = JsonNode.parse(received.next(), JsonLimits.DEFAULT);
            assertEquals(num, fragment.get("num").number());
            assertEquals(0, fragment.get("id").number());
            frame.append(fragment.get("data").string());
        }
        assertEquals((frame.length() - 1) / 100.0 + 1, total, 1e-12, "Python's true division");
        List<RobotPose> poses = new PoseDecoder(MessageType.MODEL_STATES).decode(frame.toString());
        assertEquals(ROBOTS, poses.stream().map(RobotPose::name).toList());
    }

    @Test
    void aBadSubscribeGetsNoAnswerAtAll() throws Exception {
        ReceivedFrames received = client("{\"op\":\"subscribe\",\"id\":\"b\",\"topic\":\"/tf\",\"throttle_rate\":200.0}",
                "{\"op\":\"subscribe\",\"id\":\"c\",\"topic\":\"/nothing\"}",
                "{\"op\":\"call_service\",\"id\":\"after\",\"service\":\"/rosapi/topics\"}");
        assertEquals("service_response", JsonNode.parse(received.next(), JsonLimits.DEFAULT).get("op").string(),
                "the first thing the client hears is the answer to the request after them");
    }
}
