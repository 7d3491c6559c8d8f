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
 * <li>A topic with one publisher ({@code ModelStates}, a robot's own odometry or pose): no
 * {@code throttle_rate} and no {@code queue_length} at first, so every message comes as it is
 * published, with no thread of rosbridge's between (its queue handler's thread cost a median
 * 13 ms at 20 Hz against a real rosbridge). One that sends more than
 * {@link #MOST_AS_THEY_COME} messages in a second (a simulator publishing at its physics rate:
 * Gazebo classic's 1 kHz) is asked for again, same id, with {@code throttle_rate}
 * {@link #POSE_THROTTLE_MS} and {@code queue_length} 1: at most 50 messages a second, the newest,
 * at most that late. The newest is kept per robot here and the poll takes it.</li>
 * <li>The map's grid: {@code throttle_rate} at least 1 s, {@code queue_length} 1.</li>
 * </ul>
 * Not thread-safe: the source's lock guards it.
 */
final class TopicRequests {

    /** The throttle of a topic with one publisher that sends more than {@link #MOST_AS_THEY_COME} a second. */
    static final int POSE_THROTTLE_MS = 20;

    /** The most messages a second a topic with one publisher sends as they come, unthrottled. */
    static final int MOST_AS_THEY_COME = 50;

    private static final long SECOND_NS = 1_000_000_000L;

    /**
     * One subscription: its topic, type and options, whether it is latched (sent once to each
     * subscriber: {@code /tf_static}, which a graph may also not have: not said when quiet), and
     * whether one publisher publishes it (its rate watched while it comes unthrottled).
     */
    record Topic(String name, String type, int throttleMs, int queueLength, boolean latched, boolean onePublisher) {

        /** The same subscription (its id, topic and type) throttled as a fast topic of one publisher is. */
        Topic throttled() {
            return new Topic(name, type, POSE_THROTTLE_MS, 1, latched, onePublisher);
        }

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
    /** The topics of one publisher still asked for as they come, with {@code {the start of this second, messages in it}}. */
    private final Map<String, long[]> asTheyCome = new LinkedHashMap<>();
    /** The topics no message came on yet, with when they were subscribed: said once when quiet. */
    private final Map<String, Long> waiting = new LinkedHashMap<>();
    /** The latched topics no message came on yet, with when they were last asked for. */
    private final Map<String, Long> unlatched = new LinkedHashMap<>();

    /** The topics of a run's poses that are not per robot: the topic, and /tf's /tf_static. */
    static List<Topic> poses(String topic, MessageType type) {
        List<Topic> poses = new ArrayList<>();
        if (type == MessageType.TF) {
            poses.add(new Topic(topic, type.rosName(), 0, 0, false, false));
            if (topic.endsWith("/tf")) {
                poses.add(new Topic(topic + "_static", type.rosName(), 0, 0, true, false));
            }
        } else {
            poses.add(onePublisher(topic, type));
        }
        return poses;
    }

    /** A topic one publisher publishes: a robot's own, or the simulator's list of models; as its messages come, at first. */
    static Topic onePublisher(String topic, MessageType type) {
        return new Topic(topic, type.rosName(), 0, 0, false, true);
    }

    /** The occupancy grid's topic. */
    static Topic map(String topic, int intervalMs) {
        return new Topic(topic, OccupancyGrid.TYPE, Math.max(intervalMs, 1000), 1, false, false);
    }

    /** Adds a subscription made at {@code now}; false when its topic is subscribed already. */
    boolean add(Topic topic, long now) {
        if (topics.putIfAbsent(topic.name(), topic) != null) {
            return false;
        }
        if (topic.onePublisher() && topic.throttleMs() == 0) {
            asTheyCome.put(topic.name(), new long[] {now, 0});
        }
        (topic.latched() ? unlatched : waiting).put(topic.name(), now);
        return true;
    }

    /** Whether a topic is a latched one this connection subscribed to. */
    boolean latched(String topic) {
        Topic subscribed = topics.get(topic);
        return subscribed != null && subscribed.latched();
    }

    /**
     * A message came on a topic at {@code now}. @return the subscription to ask for again when this
     * message made a topic of one publisher send more than {@link #MOST_AS_THEY_COME} in a second
     * as they come (it is throttled from now on, {@link Topic#throttled}); else null
     */
    Topic came(String topic, long now) {
        waiting.remove(topic);
        unlatched.remove(topic);
        long[] second = asTheyCome.get(topic);
        if (second == null) {
            return null;
        }
        if (now - second[0] >= SECOND_NS) {
            second[0] = now;
            second[1] = 0;
        }
        if (++second[1] <= MOST_AS_THEY_COME) {
            return null;
        }
        asTheyCome.remove(topic);
        Topic throttled = topics.get(topic).throttled();
        topics.put(topic, throttled);
        return throttled;
    }

    /**
     * The latched topics nothing came on for {@code everyNs} since they were last asked for, to ask
     * for again now. rosbridge 2.x takes a latched topic's durability from the publishers there are
     * when it subscribes: subscribed before the static broadcaster existed, it never gets what that
     * sent; a subscribe again (the same id) makes it look again. rosbridge 1 sends the latched
     * messages again, if any.
     */
    List<Topic> askAgain(long now, long everyNs) {
        List<Topic> again = new ArrayList<>();
        unlatched.replaceAll((name, asked) -> {
            if (now - asked < everyNs) {
                return asked;
            }
            again.add(topics.get(name));
            return now;
        });
        return again;
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
}
