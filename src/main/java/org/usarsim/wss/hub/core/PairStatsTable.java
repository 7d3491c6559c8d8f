package org.usarsim.wss.hub.core;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;
import org.usarsim.wss.model.RobotPair;

/**
 * The statistics of every pair the hub has seen (a DNS between them, or the model's verdict on
 * them), kept until the hub forgets the pair's ports: {@link #forget} runs when a robot's ports
 * are forgotten (wss.portMemory after it left, or was kicked). Part of the core: single-threaded.
 */
final class PairStatsTable {

    private final Map<RobotPair, PairStats> pairs = new HashMap<>();

    /** The pair's statistics, from now on when it was not seen yet. */
    PairStats of(RobotPair pair, PairState state, boolean bothPresent, long nowNs) {
        return pairs.computeIfAbsent(pair, p -> new PairStats(p, state, bothPresent, nowNs));
    }

    /** */
    PairStats get(RobotPair pair) {
        return pairs.get(pair);
    }

    /** Forgets the pairs of the robot that {@code gone} says are gone. */
    void forget(String robot, Predicate<RobotPair> gone) {
        pairs.keySet().removeIf(pair -> pair.contains(robot) && gone.test(pair));
    }

    /**
     * The robot left (or was kicked out): its pairs' time up stops counting until it is back, the
     * states they show unchanged.
     */
    void left(String robot, long nowNs) {
        pairs.values().stream().filter(stats -> stats.pair.contains(robot)).forEach(stats -> stats.absent(nowNs));
    }

    /** The pairs seen of the robot. */
    List<RobotPair> pairsOf(String robot) {
        return pairs.keySet().stream().filter(pair -> pair.contains(robot)).toList();
    }

    /** */
    List<PairStats> all() {
        return new ArrayList<>(pairs.values());
    }
}
