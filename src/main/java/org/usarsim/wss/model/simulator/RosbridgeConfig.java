package org.usarsim.wss.model.simulator;

import java.net.URI;
import java.net.URISyntaxException;
import java.util.List;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.ros.MessageType;

/**
 * The rosbridge settings of one run ({@code rosbridge.*}, docs/ros.md), read and checked at its
 * start: where the server is, the topic of the poses and its type, the root frame of {@code /tf},
 * the robots' names there, the stale limit, and the topic of the occupancy grid when the model
 * counts obstacles from one.
 *
 * @param topic      the topic, or its pattern with {@code {robot}} (one subscription per robot)
 * @param mapTopic   the topic of a {@code nav_msgs/OccupancyGrid}, or null for none
 * @param graceMs    how long a registered robot's first pose is waited for (and a new connection's first pose)
 * @param maxChars   the longest message taken, in characters, reassembled from its fragments
 */
record RosbridgeConfig(URI url, String topic, MessageType type, String frame, RobotNames names, long staleMs,
        long graceMs, int intervalMs, String mapTopic, int maxChars) {

    static final String DEFAULT_URL = "ws://127.0.0.1:9090";
    static final String DEFAULT_TOPIC = "/gazebo/model_states";
    static final String DEFAULT_FRAME = "world";
    /** The types {@code rosbridge.type} may name. */
    static final List<String> TYPES = java.util.Arrays.stream(MessageType.values()).map(MessageType::rosName).toList();
    /** A subscription that receives nothing this long is said once: rosbridge sends no error for a wrong topic or type. */
    static final long QUIET_MS = 5_000;
    /** The default of {@code rosbridge.grace}, and its least. */
    static final int DEFAULT_GRACE_MS = 10_000;
    static final int LEAST_GRACE_MS = 5_000;
    /** The stale limit when {@code rosbridge.stale} is 0: this many poll intervals. */
    static final int STALE_INTERVALS = 3;

    /** The run's rosbridge settings from its checked values; refused with the key and what is wrong. */
    static RosbridgeConfig read(ModelSettings values, int intervalMs) throws ModelStartException {
        String text = values.getString("rosbridge.url", DEFAULT_URL).strip();
        URI url;
        try {
            url = new URI(text);
        } catch (URISyntaxException e) {
            throw new ModelStartException("rosbridge.url: '" + text + "' is not a ws:// URL (" + e.getReason() + ")");
        }
        if (!("ws".equals(url.getScheme()) || "wss".equals(url.getScheme())) || url.getHost() == null) {
            throw new ModelStartException("rosbridge.url: '" + text + "' is not a ws:// or wss:// URL with a host");
        }
        String topic = values.getString("rosbridge.topic", DEFAULT_TOPIC).strip();
        if (!topic.startsWith("/") || topic.chars().anyMatch(Character::isWhitespace)) {
            throw new ModelStartException("rosbridge.topic: '" + topic + "' is not a topic name (/name/of/topic)");
        }
        String named = values.getString("rosbridge.type", "").strip();
        MessageType type = named.isEmpty() ? MessageType.ofTopic(topic.replace(RobotNames.ROBOT, "robot")).orElse(null)
                : MessageType.named(named).orElse(null);
        if (type == null) {
            throw new ModelStartException("rosbridge.type: the topic " + topic + " does not tell its type; set rosbridge.type to one of "
                    + String.join(", ", TYPES));
        }
        boolean perRobot = topic.contains(RobotNames.ROBOT);
        if (perRobot && (type == MessageType.MODEL_STATES || type == MessageType.TF)) {
            throw new ModelStartException("rosbridge.topic: " + topic + " is one topic per robot, but " + type
                    + " holds every robot: name its one topic");
        }
        if (!perRobot && (type == MessageType.ODOMETRY || type == MessageType.POSE_STAMPED)) {
            throw new ModelStartException("rosbridge.topic: " + type + " is one robot's pose: name the topic of each with "
                    + RobotNames.ROBOT + ", e.g. /{robot}/odom");
        }
        RobotNames names;
        try {
            names = RobotNames.parse(values.getString("rosbridge.names", ""),
                    type == MessageType.TF ? RobotNames.ROBOT + "/base_link" : RobotNames.ROBOT);
        } catch (IllegalArgumentException e) {
            throw new ModelStartException("rosbridge.names: " + e.getMessage());
        }
        int stale = values.getInt("rosbridge.stale", 0);
        String map = values.getString("rosbridge.map", "").strip();
        return new RosbridgeConfig(url, topic, type, values.getString("rosbridge.frame", DEFAULT_FRAME).strip(), names,
                stale > 0 ? stale : (long) STALE_INTERVALS * intervalMs, values.getInt("rosbridge.grace", DEFAULT_GRACE_MS),
                intervalMs, map.isEmpty() ? null : map,
                values.getInt("rosbridge.maxMessage", 16) * 1024 * 1024);
    }

    /** The URL and the topic, as the log says them. */
    String where() {
        return url + " " + topic;
    }

    /** The topic of one robot's poses: the topic with its source name, for a per-robot topic. */
    String topicOf(String wssRobot) {
        return topic.replace(RobotNames.ROBOT, names.model(wssRobot));
    }

    boolean perRobot() {
        return topic.contains(RobotNames.ROBOT);
    }
}
