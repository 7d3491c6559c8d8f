package org.usarsim.wss.ros;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Reads robot poses out of rosbridge frames of one message type: the one place a ROS position
 * message is read. Frames that are not {@code publish} (a {@code status}, a
 * {@code service_response}) carry no pose: {@link #decode} gives an empty list for them, and the
 * caller may log their op. A frame that is not strict JSON, or a message that lacks a field the
 * type needs or has one of the wrong kind, is a {@link JsonException} naming the path; fields
 * not needed are ignored. Not thread-safe (tf keeps the transforms of earlier messages): one
 * source's thread decodes.
 *
 * <ul>
 * <li>{@code gazebo_msgs/ModelStates}: {@code name[i]} at {@code pose[i].position}, no stamp.</li>
 * <li>{@code tf2_msgs/TFMessage}: each {@code transforms[i]} ({@code header.frame_id} to
 * {@code child_frame_id}, translation and rotation) kept; each frame whose chain to the root frame
 * changed, composed up to it, by its child frame's name.</li>
 * <li>{@code nav_msgs/Odometry} ({@code pose.pose.position}) and {@code geometry_msgs/PoseStamped}
 * ({@code pose.position}), by the robot the topic names ({@code /{robot}/odom}), in the
 * message's own frame ({@code header.frame_id}, not transformed).</li>
 * </ul>
 * Stamps: {@code header.stamp} as ROS 1 ({@code secs}, {@code nsecs}) or ROS 2 ({@code sec},
 * {@code nanosec}) writes it.
 */
public final class PoseDecoder {

    /** The default root frame of tf chains. */
    public static final String DEFAULT_ROOT_FRAME = "world";
    /** The default per-robot topic of {@code Odometry} and {@code PoseStamped}. */
    public static final String DEFAULT_ROBOT_TOPIC = "/{robot}/odom";
    /** Where a per-robot topic pattern has the robot's name. */
    public static final String ROBOT = "{robot}";

    private final MessageType type;
    private final JsonLimits limits;
    private final String topicPrefix;
    private final String topicSuffix;
    private final TfTree tf;

    /**
     * @param type the messages' type
     * @param rootFrame the frame tf chains are composed up to ({@link #DEFAULT_ROOT_FRAME})
     * @param robotTopic the per-robot topic pattern of {@code Odometry} and {@code PoseStamped}, with
     *     {@link #ROBOT} once ({@link #DEFAULT_ROBOT_TOPIC})
     * @param limits the limits of each frame's JSON
     */
    public PoseDecoder(MessageType type, String rootFrame, String robotTopic, JsonLimits limits) {
        int robot = robotTopic.indexOf(ROBOT);
        if (robot < 0 || robotTopic.indexOf(ROBOT, robot + 1) >= 0) {
            throw new IllegalArgumentException("a robot topic has " + ROBOT + " once: " + robotTopic);
        }
        this.type = type;
        this.limits = limits;
        this.topicPrefix = robotTopic.substring(0, robot);
        this.topicSuffix = robotTopic.substring(robot + ROBOT.length());
        this.tf = new TfTree(rootFrame);
    }

    /** A decoder with the default root frame, robot topic and limits. */
    public PoseDecoder(MessageType type) {
        this(type, DEFAULT_ROOT_FRAME, DEFAULT_ROBOT_TOPIC, JsonLimits.DEFAULT);
    }

    public MessageType type() {
        return type;
    }

    /** The poses one text frame carries (empty for a frame that is not a {@code publish}). */
    public List<RobotPose> decode(String text) throws JsonException {
        return decode(RosFrame.parse(text, limits));
    }

    /** The poses a parsed frame carries (empty for a frame that is not a {@code publish}). */
    public List<RobotPose> decode(RosFrame frame) throws JsonException {
        if (!frame.isPublish()) {
            return List.of();
        }
        JsonNode msg = frame.msg();
        return switch (type) {
            case MODEL_STATES -> modelStates(msg);
            case TF -> tf.update(transforms(msg));
            case ODOMETRY -> List.of(pose(robotOf(frame), msg.get("pose").get("pose"), stamp(msg)));
            case POSE_STAMPED -> List.of(pose(robotOf(frame), msg.get("pose"), stamp(msg)));
        };
    }

    /** The robot a per-robot topic names; an error when the frame's topic does not match the pattern. */
    public String robotOf(RosFrame frame) throws JsonException {
        String topic = frame.topic();
        if (topic == null) {
            throw JsonException.in("topic", "missing: a " + type + " message is one robot's, named by its topic");
        }
        if (topic.length() > topicPrefix.length() + topicSuffix.length() && topic.startsWith(topicPrefix)
                && topic.endsWith(topicSuffix)) {
            return topic.substring(topicPrefix.length(), topic.length() - topicSuffix.length());
        }
        throw JsonException.in("topic", JsonException.shortened(topic) + " does not name a robot as " + topicPrefix + ROBOT + topicSuffix + " does");
    }

    private static List<RobotPose> modelStates(JsonNode msg) throws JsonException {
        List<JsonNode> names = msg.get("name").items();
        List<JsonNode> poses = msg.get("pose").items();
        if (names.size() != poses.size()) {
            throw msg.get("pose").problem(poses.size() + " poses for " + names.size() + " names");
        }
        List<RobotPose> result = new ArrayList<>(names.size());
        for (int i = 0; i < names.size(); i++) {
            result.add(pose(names.get(i).string(), poses.get(i), RobotPose.NO_STAMP));
        }
        return result;
    }

    private static RobotPose pose(String name, JsonNode pose, long stamp) throws JsonException {
        JsonNode position = pose.get("position");
        return new RobotPose(name, position.get("x").number(), position.get("y").number(), position.get("z").number(), stamp);
    }

    private static Map<String, TfTree.Link> transforms(JsonNode msg) throws JsonException {
        Map<String, TfTree.Link> links = new LinkedHashMap<>();
        for (JsonNode item : msg.get("transforms").items()) {
            JsonNode header = item.get("header");
            String parent = TfTree.plain(header.get("frame_id").string());
            String child = TfTree.plain(item.get("child_frame_id").string());
            if (child.isEmpty() || child.equals(parent)) {
                throw item.get("child_frame_id").problem("a frame of its own, not " + (child.isEmpty() ? "empty" : "its parent's"));
            }
            JsonNode transform = item.get("transform");
            links.put(child, new TfTree.Link(parent, Transform.of(transform.get("translation"), transform.get("rotation")),
                    stampOf(header)));
        }
        return links;
    }

    private static long stamp(JsonNode msg) throws JsonException {
        return stampOf(msg.get("header"));
    }

    /** {@code header.stamp} in nanoseconds; {@link RobotPose#NO_STAMP} for ROS's zero time. */
    static long stampOf(JsonNode header) throws JsonException {
        JsonNode stamp = header.get("stamp");
        boolean ros2 = stamp.has("sec");
        long seconds = stamp.get(ros2 ? "sec" : "secs").integer(0, 9_000_000_000L);
        long nanos = stamp.get(ros2 ? "nanosec" : "nsecs").integer(0, 999_999_999L);
        long total = seconds * 1_000_000_000L + nanos;
        return total == 0 ? RobotPose.NO_STAMP : total;
    }
}
