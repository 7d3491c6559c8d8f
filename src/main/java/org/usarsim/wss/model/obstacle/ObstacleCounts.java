package org.usarsim.wss.model.obstacle;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Predicate;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.simulator.ReportedRobot;

/**
 * The latest obstacle count the simulator gave per pair, and where the two robots were when it was
 * asked: a count is asked again once either robot has moved more than the cache distance from
 * there, and at every poll while it is unknown.
 */
final class ObstacleCounts {

    private record Entry(double count, ReportedRobot first, ReportedRobot second) {
    }

    private final double cacheDistance;
    private final Map<RobotPair, Entry> entries = new ConcurrentHashMap<>();

    ObstacleCounts(double cacheDistance) {
        this.cacheDistance = cacheDistance;
    }

    /** The pair's latest count; NaN when it was never asked or the simulator did not know it. */
    double count(RobotPair pair) {
        Entry entry = entries.get(pair);
        return entry == null ? Double.NaN : entry.count();
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
