package org.usarsim.wss.ros;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** tf's transforms kept across messages and composed, translation and rotation, up to the root frame. */
class TfChainTest {

    private static final double EPSILON = 1e-9;

    /** One transform of a TFMessage: parent to child, a translation and a rotation about z (degrees). */
    static String transform(String parent, String child, double x, double y, double yawDegrees, long secs) {
        double half = Math.toRadians(yawDegrees) / 2;
        return transform(parent, child, x, y, 0, 0, 0, Math.sin(half), Math.cos(half), secs);
    }

    static String transform(String parent, String child, double x, double y, double z,
            double qx, double qy, double qz, double qw, long secs) {
        return "{\"header\":{\"seq\":0,\"stamp\":{\"secs\":" + secs + ",\"nsecs\":5},\"frame_id\":\"" + parent + "\"},"
                + "\"child_frame_id\":\"" + child + "\",\"transform\":{\"translation\":{\"x\":" + x + ",\"y\":" + y
                + ",\"z\":" + z + "},\"rotation\":{\"x\":" + qx + ",\"y\":" + qy + ",\"z\":" + qz + ",\"w\":" + qw + "}}}";
    }

    static String message(String... transforms) {
        return "{\"op\":\"publish\",\"topic\":\"\\/tf\",\"msg\":{\"transforms\":[" + String.join(",", transforms) + "]}}";
    }

    private static Map<String, RobotPose> byName(List<RobotPose> poses) {
        return poses.stream().collect(Collectors.toMap(RobotPose::name, Function.identity()));
    }

    private final PoseDecoder decoder = new PoseDecoder(MessageType.TF, "map", PoseDecoder.DEFAULT_ROBOT_TOPIC, JsonLimits.DEFAULT);

    @Test
    void aChainOfPartialMessagesIsComposedWithItsRotations() throws JsonException {
        // map -> Scout/odom: 10, 5, turned 90 degrees; Scout/odom -> Scout/base_link: 2 m ahead, turned 90 more.
        Map<String, RobotPose> first = byName(decoder.decode(message(transform("map", "Scout/odom", 10, 5, 90, 1))));
        assertEquals(10, first.get("Scout/odom").x(), EPSILON);
        assertEquals(5, first.get("Scout/odom").y(), EPSILON);

        Map<String, RobotPose> second = byName(decoder.decode(message(transform("Scout/odom", "Scout/base_link", 2, 0, 90, 2))));
        assertEquals(List.of("Scout/base_link"), List.copyOf(second.keySet()), "only the chain that changed");
        RobotPose base = second.get("Scout/base_link");
        assertEquals(10, base.x(), EPSILON);
        assertEquals(7, base.y(), EPSILON);
        assertEquals(2_000_000_005L, base.stampNanos(), "the frame's own transform's stamp");

        // A frame further down, 1 m along base_link's x, which faces -x in map (90 + 90 degrees).
        Map<String, RobotPose> third = byName(decoder.decode(message(transform("Scout/base_link", "Scout/laser", 1, 0, 0, 3))));
        assertEquals(9, third.get("Scout/laser").x(), EPSILON);
        assertEquals(7, third.get("Scout/laser").y(), EPSILON);

        // The map's correction moves everything below it.
        Map<String, RobotPose> fourth = byName(decoder.decode(message(transform("map", "Scout/odom", 0, 0, 0, 4))));
        assertEquals(List.of("Scout/base_link", "Scout/laser", "Scout/odom"), fourth.keySet().stream().sorted().toList());
        assertEquals(2, fourth.get("Scout/base_link").x(), EPSILON);
        assertEquals(0, fourth.get("Scout/base_link").y(), EPSILON);
        assertEquals(2, fourth.get("Scout/laser").x(), EPSILON);
        assertEquals(1, fourth.get("Scout/laser").y(), EPSILON);
    }

    @Test
    void aRotationOutOfTheFloorTurnsTheChildsTranslation() throws JsonException {
        double s = Math.sqrt(0.5);
        // Rolled 90 degrees about x: the child's +y is the parent's +z.
        decoder.decode(message(transform("map", "arm", 1, 0, 0, s, 0, 0, s, 1)));
        RobotPose tip = byName(decoder.decode(message(transform("arm", "tip", 0, 1, 0, 0, 0, 0, 1, 1)))).get("tip");
        assertEquals(1, tip.x(), EPSILON);
        assertEquals(0, tip.y(), EPSILON);
        assertEquals(1, tip.z(), EPSILON);
    }

    @Test
    void anUnnormalisedQuaternionIsNormalisedAndAZeroOneRefused() throws JsonException {
        decoder.decode(message(transform("map", "a", 0, 0, 0, 0, 0, 2, 2, 1)));
        RobotPose b = byName(decoder.decode(message(transform("a", "b", 1, 0, 0, 0, 0, 0, 1, 1)))).get("b");
        assertEquals(0, b.x(), EPSILON);
        assertEquals(1, b.y(), EPSILON);
        JsonException e = assertThrows(JsonException.class, () -> decoder.decode(message(transform("map", "c", 0, 0, 0, 0, 0, 0, 0, 1))));
        assertEquals("msg.transforms[0].transform.rotation: not a rotation: a quaternion of length 0.0", e.getMessage());
    }

    @Test
    void framesWithoutAChainToTheRootAreLeftOutUntilTheyHaveOne() throws JsonException {
        assertEquals(List.of(), decoder.decode(message(transform("odom", "base_link", 1, 1, 0, 1))));
        Map<String, RobotPose> linked = byName(decoder.decode(message(transform("/map", "/odom", 1, 0, 0, 1))));
        assertEquals(2, linked.get("base_link").x(), EPSILON, "a leading / is the same frame");
        assertEquals(1, linked.get("base_link").y(), EPSILON);
    }

    @Test
    void aLoopOfFramesEndsAndGivesNothing() throws JsonException {
        assertEquals(List.of(), decoder.decode(message(transform("a", "b", 1, 0, 0, 1), transform("b", "a", 1, 0, 0, 1))));
        assertTrue(decoder.decode(message(transform("map", "c", 1, 0, 0, 1))).stream().anyMatch(p -> p.name().equals("c")));
    }

    @Test
    void aFrameWhosePoseAddsUpToInfinityIsLeftOut() throws JsonException {
        decoder.decode(message(transform("map", "far", 1e308, 0, 0, 1)));
        assertEquals(List.of(), decoder.decode(message(transform("far", "beyond", 1e308, 0, 0, 1))));
        assertEquals(List.of("beyond", "far"), decoder.decode(message(transform("map", "far", 0, 0, 0, 1))).stream()
                .map(RobotPose::name).sorted().toList(), "back within reach");
    }

    @Test
    void theOldTfTypeNameAndRos2TypeNamesAreTf() {
        assertEquals(MessageType.TF, MessageType.named("tf/tfMessage").orElseThrow());
        assertEquals(MessageType.TF, MessageType.named("tf2_msgs/msg/TFMessage").orElseThrow());
        assertEquals(MessageType.ODOMETRY, MessageType.named("nav_msgs/msg/Odometry").orElseThrow());
        assertTrue(MessageType.named("foo_msgs/Bar").isEmpty());
        assertEquals(MessageType.MODEL_STATES, MessageType.ofTopic("/model_states").orElseThrow());
        assertEquals(MessageType.TF, MessageType.ofTopic("/tf_static").orElseThrow());
        assertTrue(MessageType.ofTopic("/odom").isEmpty(), "no robot in the topic");
        assertTrue(MessageType.ofTopic("/Scout/pose").isEmpty(), "the type must be given");
    }

    @Test
    void aRos2StampIsReadAndZeroIsNoStamp() throws JsonException {
        PoseDecoder odometry = new PoseDecoder(MessageType.POSE_STAMPED, "world", "/robots/{robot}/pose", JsonLimits.DEFAULT);
        RobotPose pose = odometry.decode("{\"op\":\"publish\",\"topic\":\"/robots/Mapper/pose\",\"msg\":{\"header\":{\"stamp\":"
                + "{\"sec\":3,\"nanosec\":7},\"frame_id\":\"world\"},\"pose\":{\"position\":{\"x\":1,\"y\":2,\"z\":3},"
                + "\"orientation\":{\"x\":0,\"y\":0,\"z\":0,\"w\":1}}}}").get(0);
        assertEquals(new RobotPose("Mapper", 1, 2, 3, 3_000_000_007L), pose);
        RobotPose zero = odometry.decode("{\"op\":\"publish\",\"topic\":\"/robots/Mapper/pose\",\"msg\":{\"header\":{\"stamp\":"
                + "{\"sec\":0,\"nanosec\":0}},\"pose\":{\"position\":{\"x\":1,\"y\":2,\"z\":3}}}}").get(0);
        assertEquals(RobotPose.NO_STAMP, zero.stampNanos());
        JsonException e = assertThrows(JsonException.class, () -> odometry.decode("{\"op\":\"publish\",\"topic\":\"/Mapper/odom\","
                + "\"msg\":{}}"));
        assertEquals("topic: /Mapper/odom does not name a robot as /robots/{robot}/pose does", e.getMessage());
    }
}
