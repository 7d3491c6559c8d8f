package org.usarsim.wss.world;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The ROS graph the world server's rosbridge side stands for: which publishers publish which
 * topic, and when, in the world's time (nanoseconds since it started), as a Gazebo world with a
 * robot_state_publisher and an odometry node per robot publishes it (docs/world.md, "Over
 * rosbridge"). Every periodic publisher publishes at the same rate, publisher {@code k} of a
 * topic at {@code phase_k + n * period} for n = 0, 1, ...:
 * <ul>
 * <li>{@code /gazebo/model_states}: one publisher, phase 0;</li>
 * <li>{@code /tf}: one publisher per robot (its own {@code world -> NAME/base_link}), robot
 * {@code i} of {@code N} (file order) at phase {@code period * i / N}: staggered;</li>
 * <li>{@code /NAME/odom}: one publisher, at its robot's phase; a client's first message of it
 * comes only after the connection delay ({@link #startDelay}), as a rospy subscriber's connection
 * to a publisher is made;</li>
 * <li>{@code /tf_static} ({@code map -> world}) and {@code /map}: latched, published once at 0.</li>
 * </ul>
 * Pure: the time is passed in.
 */
final class RosGraph {

    static final String MODEL_STATES = "/gazebo/model_states";
    static final String TF = "/tf";
    static final String TF_STATIC = "/tf_static";
    static final String MAP = "/map";
    static final String ODOM_SUFFIX = "/odom";
    /** The publishers' rate unless told otherwise ({@code --ros-rate}). */
    static final double DEFAULT_RATE_HZ = 20;
    /** The highest rate taken: a period of a millisecond. */
    static final double MAX_RATE_HZ = 1000;
    /** How long a subscriber's connection to a per-robot topic's publisher takes unless told otherwise. */
    static final long DEFAULT_CONNECTION_DELAY_NANOS = 300_000_000L;

    /**
     * A publisher: its topic and type, its robot (its index in file order; -1: none), its phase;
     * a latched one publishes once, at 0, and each new subscription gets that message.
     */
    record Publisher(String topic, String type, int robot, long phaseNanos, boolean latched) {
    }

    /** One message of a publisher, published at {@code nanos}, its {@code seq}-th (from 0). */
    record Publication(Publisher publisher, long nanos, long seq) {
    }

    private final List<String> robots;
    private final long periodNanos;
    private final long connectionDelayNanos;
    private final Map<String, List<Publisher>> byTopic = new LinkedHashMap<>();
    private final Map<String, String> types = new LinkedHashMap<>();

    /**
     * @param robots the robots' names, in file order
     * @throws IllegalArgumentException a rate that is not above 0 and at most {@link #MAX_RATE_HZ}, or a negative delay
     */
    RosGraph(List<String> robots, double rateHz, long connectionDelayNanos) {
        this.robots = List.copyOf(robots);
        this.periodNanos = periodNanos(rateHz);
        if (connectionDelayNanos < 0) {
            throw new IllegalArgumentException("a connection delay of 0 or more: " + connectionDelayNanos + " ns");
        }
        this.connectionDelayNanos = connectionDelayNanos;
        add(new Publisher(MODEL_STATES, "gazebo_msgs/ModelStates", -1, 0, false));
        types.put(TF, "tf2_msgs/TFMessage");
        int count = robots.size();
        for (int i = 0; i < count; i++) {
            add(new Publisher(TF, "tf2_msgs/TFMessage", i, periodNanos * i / count, false));
        }
        add(new Publisher(TF_STATIC, "tf2_msgs/TFMessage", -1, 0, true));
        add(new Publisher(MAP, "nav_msgs/OccupancyGrid", -1, 0, true));
        for (int i = 0; i < count; i++) {
            add(new Publisher(odomTopic(robots.get(i)), "nav_msgs/Odometry", i, periodNanos * i / count, false));
        }
    }

    private void add(Publisher publisher) {
        types.put(publisher.topic(), publisher.type());
        byTopic.computeIfAbsent(publisher.topic(), topic -> new ArrayList<>()).add(publisher);
    }

    static String odomTopic(String robot) {
        return "/" + robot + ODOM_SUFFIX;
    }

    /** The period of a rate. */
    static long periodNanos(double rateHz) {
        if (!(rateHz > 0 && rateHz <= MAX_RATE_HZ)) {
            throw new IllegalArgumentException("a rate above 0 and at most " + (int) MAX_RATE_HZ + " Hz: " + rateHz);
        }
        return Math.round(1e9 / rateHz);
    }

    /** The topics published, in the order of the start line. */
    List<String> topics() {
        return List.copyOf(types.keySet());
    }

    /** The type of a topic published, or null for a topic nobody publishes. */
    String type(String topic) {
        return types.get(topic);
    }

    /** The topic's latched publisher, or null when it has none. */
    Publisher latched(String topic) {
        return byTopic.getOrDefault(topic, List.of()).stream().filter(Publisher::latched).findFirst().orElse(null);
    }

    /**
     * How long after a client subscribes its first message of the topic may come: the connection
     * delay for a per-robot topic ({@code /NAME/odom}), 0 for the others.
     */
    long startDelay(String topic) {
        return topic.endsWith(ODOM_SUFFIX) && types.containsKey(topic) ? connectionDelayNanos : 0;
    }

    /**
     * The topic's next publications strictly after {@code after}: every periodic publisher's that
     * falls at the earliest such instant (usually one); none for a latched or unknown topic.
     */
    List<Publication> next(String topic, long after) {
        List<Publication> next = new ArrayList<>(1);
        long first = Long.MAX_VALUE;
        for (Publisher publisher : byTopic.getOrDefault(topic, List.of())) {
            if (publisher.latched()) {
                continue;
            }
            long at = atOrAfter(publisher.phaseNanos(), periodNanos, after + 1);
            if (at < first) {
                next.clear();
                first = at;
            }
            if (at == first) {
                next.add(new Publication(publisher, at, (at - publisher.phaseNanos()) / periodNanos));
            }
        }
        return next;
    }

    /**
     * The first instant at or after {@code t} at which the topic's publisher publishes (on
     * {@code /tf}, the named robot's; on the others their one publisher, whatever {@code robot}
     * is); {@link Long#MAX_VALUE} when a latched topic's one message (at 0) is before {@code t}.
     *
     * @throws IllegalArgumentException a topic nobody publishes, or {@code /tf} without one of its robots
     */
    long firstPublishAtOrAfter(String topic, String robot, long t) {
        List<Publisher> publishers = byTopic.getOrDefault(topic, List.of());
        if (publishers.isEmpty()) {
            throw new IllegalArgumentException("nobody publishes " + topic + ": " + topics());
        }
        Publisher publisher = publishers.stream().filter(p -> !topic.equals(TF) || robots.get(p.robot()).equals(robot)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException(topic + " is published for " + robots + ", not for " + robot));
        if (publisher.latched()) {
            return t <= 0 ? 0 : Long.MAX_VALUE;
        }
        return atOrAfter(publisher.phaseNanos(), periodNanos, t);
    }

    /** The first {@code phase + n * period} (n = 0, 1, ...) at or after {@code t}. */
    static long atOrAfter(long phase, long period, long t) {
        if (t <= phase) {
            return phase;
        }
        return phase + Math.floorDiv(t - phase + period - 1, period) * period;
    }
}
