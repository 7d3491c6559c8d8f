package org.usarsim.wss.model.simulator;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.ros.Json;
import org.usarsim.wss.ros.MessageType;
import org.usarsim.wss.ros.OccupancyGrid;

/**
 * What one rosbridge connection subscribes to, with which options (docs/ros.md, "The
 * subscriptions"), and which of its topics have sent nothing yet. The options are chosen for what
 * rosbridge_library's subscribe does with them:
 *
 * <ul>
 * <li>{@code /tf} and {@code /tf_static}: no {@code throttle_rate} and no {@code queue_length},
 * so every message of every publisher comes as it is published. A throttle passes one message
 * per interval whoever published it (the others are lost), and a queue of one drops a message
 * that another follows before rosbridge's sending thread takes it: /tf always has several
 * publishers.</li>
 * <li>A topic with one publisher ({@code ModelStates}, a robot's own odometry or pose):
 * {@code throttle_rate} {@link #POSE_THROTTLE_MS} with {@code queue_length} 1, so that a
 * simulator publishing at its physics rate costs at most 50 messages a second, and a message is
 * at most that late: the newest is kept per robot here and the poll takes it.</li>
 * <li>The map's grid: {@code throttle_rate} at least 1 s, {@code queue_length} 1.</li>
 * </ul>
 * Not thread-safe: the source's lock guards it.
 */
final class TopicRequests {

    /** The throttle of a topic with one publisher. */
    static final int POSE_THROTTLE_MS = 20;

    /**
     * One subscription: its topic, type and options, and whether it is said when nothing comes on
     * it for 5 s (not {@code /tf_static}, which a graph may not have).
     */
    record Topic(String name, String type, int throttleMs, int queueLength, boolean quietSaid) {

        /** The rosbridge v2 subscribe request. */
        String request() {
            Map<String, Object> request = new LinkedHashMap<>();
            request.put("op", "subscribe");
            request.put("id", "wss:" + name);
            request.put("topic", name);
            request.put("type", type);
            request.put("throttle_rate", throttleMs);
            request.put("queue_length", queueLength);
            return Json.write(request);
        }
    }

    private final Map<String, Topic> topics = new LinkedHashMap<>();
    /** The topics no message came on yet, with when they were subscribed. */
    private final Map<String, Long> waiting = new LinkedHashMap<>();

    /** The topics of a run's poses that are not per robot: the topic, and /tf's /tf_static. */
    static List<Topic> poses(String topic, MessageType type) {
        List<Topic> poses = new ArrayList<>();
        if (type == MessageType.TF) {
            poses.add(new Topic(topic, type.rosName(), 0, 0, true));
            if (topic.endsWith("/tf")) {
                poses.add(new Topic(topic + "_static", type.rosName(), 0, 0, false));
            }
        } else {
            poses.add(onePublisher(topic, type));
        }
        return poses;
    }

    /** A topic one publisher publishes: a robot's own, or the simulator's list of models. */
    static Topic onePublisher(String topic, MessageType type) {
        return new Topic(topic, type.rosName(), POSE_THROTTLE_MS, 1, true);
    }

    /** The occupancy grid's topic. */
    static Topic map(String topic, int intervalMs) {
        return new Topic(topic, OccupancyGrid.TYPE, Math.max(intervalMs, 1000), 1, true);
    }

    /** Adds a subscription made at {@code now}; false when its topic is subscribed already. */
    boolean add(Topic topic, long now) {
        if (topics.putIfAbsent(topic.name(), topic) != null) {
            return false;
        }
        if (topic.quietSaid()) {
            waiting.put(topic.name(), now);
        }
        return true;
    }

    /** A message came on a topic. */
    void came(String topic) {
        waiting.remove(topic);
    }

    /** The subscribed topics that have sent nothing for {@code quietNs} at {@code now}, each given once. */
    List<Topic> quiet(long now, long quietNs) {
        List<Topic> quiet = new ArrayList<>();
        waiting.entrySet().removeIf(entry -> {
            if (now - entry.getValue() >= quietNs) {
                quiet.add(topics.get(entry.getKey()));
                return true;
            }
            return false;
        });
        return quiet;
    }

    boolean isEmpty() {
        return topics.isEmpty();
    }
}
