package org.usarsim.wss.ros;

import java.util.Optional;

/** The ROS message types positions are read from, with the topics that tell them. */
public enum MessageType {
    /** {@code name[]} and {@code pose[]}, in Gazebo's world frame; no stamp. */
    MODEL_STATES("gazebo_msgs/ModelStates"),
    /** Transforms parent to child, composed up to the root frame; {@code tf/tfMessage} is the same. */
    TF("tf2_msgs/TFMessage"),
    /** One robot's {@code pose.pose} on its own topic ({@code /{robot}/odom}). */
    ODOMETRY("nav_msgs/Odometry"),
    /** One robot's {@code pose} on its own topic. */
    POSE_STAMPED("geometry_msgs/PoseStamped");

    private final String rosName;

    MessageType(String rosName) {
        this.rosName = rosName;
    }

    /** The type as rosbridge names it in a subscribe ({@code gazebo_msgs/ModelStates}). */
    public String rosName() {
        return rosName;
    }

    /**
     * The type of a ROS type name: ROS 1's {@code package/Type}, ROS 2's {@code package/msg/Type},
     * and tf's old {@code tf/tfMessage}; empty for any other.
     */
    public static Optional<MessageType> named(String name) {
        String plain = name.replace("/msg/", "/");
        if (plain.equals("tf/tfMessage")) {
            return Optional.of(TF);
        }
        for (MessageType type : values()) {
            if (type.rosName.equals(plain)) {
                return Optional.of(type);
            }
        }
        return Optional.empty();
    }

    /**
     * The type a topic tells: {@code /gazebo/model_states} (and ROS 2's gazebo_ros default
     * {@code /model_states}), {@code /tf} and {@code /tf_static}, any topic ending in
     * {@code /odom}; empty for the others (the type must then be given).
     */
    public static Optional<MessageType> ofTopic(String topic) {
        return switch (topic) {
            case "/gazebo/model_states", "/model_states" -> Optional.of(MODEL_STATES);
            case "/tf", "/tf_static" -> Optional.of(TF);
            default -> topic.endsWith("/odom") && topic.length() > "/odom".length() ? Optional.of(ODOMETRY) : Optional.empty();
        };
    }

    @Override
    public String toString() {
        return rosName;
    }
}
