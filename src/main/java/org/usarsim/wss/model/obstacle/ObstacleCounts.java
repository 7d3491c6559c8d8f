package org.usarsim.wss.model.obstacle;

import java.util.Collection;
import java.util.HashMap;
import java.util.Map;
import java.util.function.Predicate;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.simulator.ReportedRobot;

/**
 * The latest obstacle count the simulator gave per pair, and where the two robots were when it was
 * asked: a count is asked again once either robot has moved more than the cache distance from
 * there, and at every poll while it is unknown. Used by the poller only: what it answers is
 * published with the poll's positions.
 */
final class ObstacleCounts {

    private record Entry(double count, ReportedRobot first, ReportedRobot second) {
    }

    private final double cacheDistance;
    private final Map<RobotPair, Entry> entries = new HashMap<>();

    ObstacleCounts(double cacheDistance) {
        this.cacheDistance = cacheDistance;
    }

    /** The latest count of each of these pairs that has one; NaN where the simulator did not know it. */
    Map<RobotPair, Double> counts(Collection<RobotPair> pairs) {
        Map<RobotPair, Double> known = new HashMap<>();
        for (RobotPair pair : pairs) {
            Entry entry = entries.get(pair);
            if (entry != null) {
                known.put(pair, entry.count());
            }
        }
        return known;
    }

    /** Whether the pair's count must be asked (again) now that its robots are at {@code positions}. */
    boolean stale(RobotPair pair, Map<String, ReportedRobot> positions) {
        Entry entry = entries.get(pair);
        return entry == null || Double.isNaN(entry.count())
                || positions.get(pair.first()).distanceTo(entry.first()) > cacheDistance
                || positions.get(pair.second()).distanceTo(entry.second()) > cacheDistance;
    }

    /** Remembers a count (NaN: unknown), asked while the pair's robots were at {@code positions}. */
    void put(RobotPair pair, double count, Map<String, ReportedRobot> positions) {
        entries.put(pair, new Entry(count, positions.get(pair.first()), positions.get(pair.second())));
    }

    /** Forgets the pairs for which {@code keep} says no. */
    void retain(Predicate<RobotPair> keep) {
        entries.keySet().removeIf(keep.negate());
    }
}
