package org.usarsim.wss.model.simulator;

import java.util.Collection;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import org.usarsim.wss.ros.RobotPose;

/**
 * What one rosbridge connection has learnt of the robots (docs/ros.md, "Silent or unlisted"): the
 * latest pose of each, with its stamp and arrival, and the three rules read from it. Pure: the time
 * is passed in; the caller holds the lock.
 *
 * <ul>
 * <li><b>Listed</b>: a robot whose latest pose is fresh, by its stamp against the newest stamp
 * where it has one (ROS time may be simulation time), by its arrival where not. Null before the
 * first readable pose: a connection that knows nothing lists nothing, not "nobody".</li>
 * <li><b>Waited for</b>: a registered robot this connection never had a pose of, within the
 * grace since it was first asked about (or since the connection opened): neither listed nor
 * unlisted, so not kicked. A per-robot topic's first message comes only once rosbridge has
 * subscribed to it in ROS; a robot's publisher may start after its INIT. After the grace it is
 * unlisted, and kicked.</li>
 * <li><b>Silent</b>: no readable pose for the stale limit (before the first one: the longer of
 * the stale limit and the grace, from the opening). A message that cannot be read is no sign of
 * life: a source sending only such messages is silent, not empty, and nobody is kicked.</li>
 * </ul>
 */
final class PoseTable {

    /** One kept pose: where, its stamp ({@link RobotPose#NO_STAMP} for none), when it arrived. */
    private record Entry(ReportedRobot robot, long stamp, long arrival) {
    }

    private final long staleNs;
    private final long graceNs;
    private final long openedAt;
    private final Map<String, Entry> latest = new HashMap<>();
    /** Every robot this connection had a pose of. */
    private final Set<String> seen = new HashSet<>();
    /** The registered robots not seen yet, with when they were first asked about. */
    private final Map<String, Long> asked = new HashMap<>();
    private long newestStamp = Long.MIN_VALUE;
    /** When the last readable pose came, or the connection opened. */
    private long lastPoses;
    private boolean posesCame;
    /** Messages that could not be read since the last readable pose. */
    private int unreadable;

    PoseTable(long staleNs, long graceNs, long openedAt) {
        this.staleNs = staleNs;
        this.graceNs = graceNs;
        this.openedAt = openedAt;
        this.lastPoses = openedAt;
    }

    /**
     * Takes one readable message's poses, by WSS name (a source name that is no WSS robot already
     * left out). {@code wholeList}: the message lists every model ({@code ModelStates}), so one it
     * does not list is gone at once. {@code live}: the message came on a topic that publishes
     * on, a sign of life; a latched one's ({@code /tf_static}, sent once to each subscriber, again
     * after each reconnection) is not, and its poses are kept all the same.
     */
    void took(Map<String, RobotPose> poses, boolean wholeList, boolean live, long now) {
        if (live) {
            posesCame = true;
            lastPoses = now;
            unreadable = 0;
        }
        if (wholeList) {
            latest.clear();
        }
        poses.forEach((robot, pose) -> {
            latest.put(robot, new Entry(new ReportedRobot(robot, pose.x(), pose.y(), pose.z(), false), pose.stampNanos(), now));
            seen.add(robot);
            if (pose.hasStamp()) {
                newestStamp = Math.max(newestStamp, pose.stampNanos());
            }
        });
    }

    /** A message on a poses' topic that could not be read: counted, and no sign of life. */
    void unreadable() {
        unreadable++;
    }

    /**
     * Why the connection is silent at {@code now} ({@code where}: the server, as the log says it),
     * or null while it is not.
     */
    String silence(long now, String where) {
        long limit = posesCame ? staleNs : Math.max(staleNs, graceNs);
        long quiet = now - lastPoses;
        if (quiet <= limit) {
            return null;
        }
        long ms = quiet / 1_000_000;
        return unreadable == 0 ? "nothing from rosbridge at " + where + " for " + ms + " ms"
                : "nothing readable from rosbridge at " + where + " for " + ms + " ms (" + unreadable
                        + (unreadable == 1 ? " message" : " messages") + " that cannot be read)";
    }

    /** The robots listed now, by name in order; null before the first readable pose. */
    Map<String, ReportedRobot> listed(long now) {
        if (!posesCame) {
            return null;
        }
        Map<String, ReportedRobot> listed = new LinkedHashMap<>();
        latest.values().stream().filter(entry -> fresh(entry, now)).sorted(Comparator.comparing(e -> e.robot().name()))
                .forEach(entry -> listed.put(entry.robot().name(), entry.robot()));
        return listed;
    }

    /**
     * The robots of {@code registered} waited for at {@code now}: never had a pose of on this
     * connection, first asked about less than the grace ago. Robots no longer registered are
     * forgotten, so one that registers again without a pose yet has a grace of its own.
     */
    Set<String> waitedFor(Collection<String> registered, long now) {
        asked.keySet().retainAll(registered);
        Set<String> waiting = new LinkedHashSet<>();
        for (String robot : registered) {
            if (seen.contains(robot)) {
                continue;
            }
            long since = asked.computeIfAbsent(robot, r -> Math.max(now, openedAt));
            if (now - since < graceNs) {
                waiting.add(robot);
            }
        }
        return waiting;
    }

    private boolean fresh(Entry entry, long now) {
        return entry.stamp() != RobotPose.NO_STAMP ? newestStamp - entry.stamp() <= staleNs : now - entry.arrival() <= staleNs;
    }
}
