package org.usarsim.wss.ros;

/**
 * Where a ROS message puts a model or a frame, in metres in the root frame (x and y on the floor,
 * z up, as ROS's REP 103 and USARSim's frame agree), and when.
 *
 * @param name the model's name ({@code gazebo_msgs/ModelStates}), the child frame
 *     ({@code tf2_msgs/TFMessage}, without a leading {@code /}) or the robot of the topic
 *     ({@code /{robot}/odom})
 * @param stampNanos the message's stamp (ROS time, which may be simulation time: compare stamps
 *     with each other, not with the clock) in nanoseconds, or {@link #NO_STAMP} when the message
 *     has none ({@code ModelStates}) or its stamp is zero (ROS's "no time")
 */
public record RobotPose(String name, double x, double y, double z, long stampNanos) {

    /** The stamp of a pose whose message has none. */
    public static final long NO_STAMP = -1;

    public boolean hasStamp() {
        return stampNanos != NO_STAMP;
    }
}
