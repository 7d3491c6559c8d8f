package org.usarsim.wss.hub.core;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.usarsim.wss.model.RobotPair;

/**
 * The hub's WSS ports: by key, and indexed by robot pair and by robot, so that a break, a resume
 * or a robot's departure touches only the ports it concerns. The indexes are derived here and
 * nowhere else; every collection keeps the order the ports were added in. Single-threaded, as the whole core.
 */
final class Ports {

    private final Map<PortKey, WssPort> byKey = new LinkedHashMap<>();
    private final Map<RobotPair, Set<WssPort>> byPair = new HashMap<>();
    private final Map<String, Set<WssPort>> byRobot = new HashMap<>();
    /** How many ports each robot is the source of (kept with the indexes: a DNS asks it every time). */
    private final Map<String, Integer> fromCounts = new HashMap<>();

    WssPort get(PortKey key) {
        return byKey.get(key);
    }

    void add(WssPort port) {
        PortKey key = port.key;
        if (byKey.putIfAbsent(key, port) != null) {
            throw new IllegalStateException("a port for " + key + " already");
        }
        byPair.computeIfAbsent(key.pair(), p -> new LinkedHashSet<>()).add(port);
        byRobot.computeIfAbsent(key.from(), r -> new LinkedHashSet<>()).add(port);
        byRobot.computeIfAbsent(key.to(), r -> new LinkedHashSet<>()).add(port);
        fromCounts.merge(key.from(), 1, Integer::sum);
    }

    void remove(WssPort port) {
        PortKey key = port.key;
        if (byKey.remove(key, port)) {
            removeFrom(byPair, key.pair(), port);
            removeFrom(byRobot, key.from(), port);
            removeFrom(byRobot, key.to(), port);
            fromCounts.computeIfPresent(key.from(), (robot, count) -> count == 1 ? null : count - 1);
        }
    }

    private static <K> void removeFrom(Map<K, Set<WssPort>> index, K at, WssPort port) {
        Set<WssPort> set = index.get(at);
        set.remove(port);
        if (set.isEmpty()) {
            index.remove(at);
        }
    }

    /** Every port, in the order they were added. */
    Collection<WssPort> all() {
        return Collections.unmodifiableCollection(byKey.values());
    }

    /** The ports between the two robots, either way (a copy: the caller may remove them). */
    List<WssPort> between(RobotPair pair) {
        return new ArrayList<>(byPair.getOrDefault(pair, Set.of()));
    }

    /** The ports the robot is the source or the target of (a copy: the caller may remove them). */
    List<WssPort> of(String robot) {
        return new ArrayList<>(byRobot.getOrDefault(robot, Set.of()));
    }

    /** How many ports have the robot as source. */
    int fromCount(String robot) {
        return fromCounts.getOrDefault(robot, 0);
    }

    void clear() {
        byKey.clear();
        byPair.clear();
        byRobot.clear();
        fromCounts.clear();
    }
}
