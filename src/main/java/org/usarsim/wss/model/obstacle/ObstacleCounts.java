package org.usarsim.wss.model.obstacle;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Predicate;
import org.usarsim.wss.model.distance.NamePair;
import org.usarsim.wss.model.distance.RobotState;

/**
 * The obstacle counts the simulator gave per pair, each valid until either robot has moved more
 * than the cache distance from where it was when the count was asked.
 */
final class ObstacleCounts {

    private record Entry(double count, RobotState first, RobotState second) {
    }

    private final double cacheDistance;
    private final Map<NamePair, Entry> entries = new ConcurrentHashMap<>();

    ObstacleCounts(double cacheDistance) {
        this.cacheDistance = cacheDistance;
    }

    /** The count for these two robots at these positions, or NaN when none is known for them. */
    double count(RobotState a, RobotState b) {
        NamePair pair = NamePair.of(a.name(), b.name());
        Entry entry = entries.get(pair);
        if (entry == null) {
            return Double.NaN;
        }
        RobotState first = pair.first().equals(a.name()) ? a : b;
        RobotState second = first == a ? b : a;
        boolean stayed = first.distanceTo(entry.first()) <= cacheDistance && second.distanceTo(entry.second()) <= cacheDistance;
        return stayed ? entry.count() : Double.NaN;
    }

    /** Remembers a known count, asked while the pair's robots were at these positions. */
    void put(NamePair pair, double count, Map<String, RobotState> positions) {
        entries.put(pair, new Entry(count, positions.get(pair.first()), positions.get(pair.second())));
    }

    /** Forgets the pairs for which {@code keep} says no. */
    void retain(Predicate<NamePair> keep) {
        entries.keySet().removeIf(keep.negate());
    }
}
