package org.usarsim.wss.hub.core;

import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Predicate;
import java.util.logging.Level;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * What the core knows of each pair of robots: the model's breaks, an operator's forces, the
 * statistics and the conditions each way ({@link PairConditions}); its state, the one rule of
 * whether it may talk ({@link #talks}), and the record of each change. Part of the {@link HubCore},
 * under its lock; the ports of a pair are the core's.
 */
final class Pairs {

    /** Pairs the model broke and has not resumed. */
    private final Set<RobotPair> broken = new HashSet<>();
    /** Pairs an operator forced down or up: they win over {@link #broken} and the model's answers. */
    private final ForcedPairs forcedPairs = new ForcedPairs();
    /** The statistics of every pair seen, forgotten with the pair's ports. */
    private final PairStatsTable stats = new PairStatsTable();
    private final PairConditions conditions;
    /** Whether a robot is registered now. */
    private final Predicate<String> registered;

    Pairs(ShapingConfig shaping, Predicate<String> registered) {
        this.registered = registered;
        this.conditions = new PairConditions(shaping, forcedPairs, this::stateOf);
    }

    /** The pair's state now: an operator's force wins over the model's verdict. */
    PairState stateOf(RobotPair pair) {
        Force force = forcedPairs.of(pair);
        if (force != null) {
            return force == Force.DOWN ? PairState.FORCED_DOWN : PairState.FORCED_UP;
        }
        return broken.contains(pair) ? PairState.BROKEN : PairState.UP;
    }

    /**
     * The rule: whether the pair may talk one way (its ports listen, its connections are
     * forwarded): forced, as forced; otherwise when the model neither broke nor forbids it.
     */
    boolean talks(RobotPair pair, boolean modelAllows) {
        return forcedPairs.allows(pair, modelAllows && !broken.contains(pair));
    }

    /** The pair's forced state, or null when the model decides it. */
    Force forced(RobotPair pair) {
        return forcedPairs.of(pair);
    }

    /**
     * The pair's statistics, from now on when it was not seen yet; its conditions both ways too
     * (their rates said, with shaping on).
     */
    PairStats seen(RobotPair pair, long nowNs, Changes out) {
        conditions.seen(pair, out);
        return stats.of(pair, stateOf(pair), bothPresent(pair), nowNs);
    }

    /** The live cell of a seen pair's condition one way. */
    LiveCondition condition(OrderedPair way) {
        return conditions.cell(way);
    }

    /** The model broke the pair. @return whether that changed its state */
    boolean broke(RobotPair pair, long nowNs, Changes out) {
        PairStats pairStats = seen(pair, nowNs, out); // first seen now: seen up until this break
        boolean changed = broken.add(pair);
        if (changed) {
            pairStats.modelChanged(true);
            record(pair, true, nowNs, out);
        }
        return changed;
    }

    /** The model resumed the pair. @return whether that changed its state */
    boolean resumed(RobotPair pair, long nowNs, Changes out) {
        PairStats pairStats = seen(pair, nowNs, out);
        boolean changed = broken.remove(pair);
        if (changed) {
            pairStats.modelChanged(false);
            record(pair, true, nowNs, out);
        }
        return changed;
    }

    /** An operator forces the pair, up with its rate and delay pinned (or not: {@link RatePin#NONE}); said once. */
    void force(RobotPair pair, Force force, RatePin pin, Changes out) {
        boolean pinned = forcedPairs.pin(pair, force == Force.UP ? pin : RatePin.NONE);
        Force before = forcedPairs.force(pair, force);
        if (before != force || pinned) { // a new rate or delay for a pair forced up is a force that changed something
            out.add(new HubEvent.PairForced(pair.first(), pair.second(), force == Force.UP));
        }
        if (pinned && force == Force.UP) {
            out.add(new HubEvent.PairPinned(pair.first(), pair.second(), pin));
        }
    }

    /** Gives the pair back to the model. @return whether it was forced (then it is said) */
    boolean release(RobotPair pair, Changes out) {
        if (forcedPairs.release(pair) == null) {
            return false;
        }
        out.add(new HubEvent.PairReleased(pair.first(), pair.second()));
        return true;
    }

    boolean isBroken(RobotPair pair) {
        return broken.contains(pair);
    }

    /**
     * Records the state now of a pair seen (after a break, a resume, a force or a release); with
     * {@code say}, a change is logged, one line (a force says itself: the event's line).
     */
    void record(RobotPair pair, boolean say, long nowNs, Changes out) {
        conditions.refresh(pair, out);
        PairStats pairStats = stats.get(pair);
        PairState now = stateOf(pair);
        if (pairStats != null && pairStats.moveTo(now, bothPresent(pair), nowNs) && say) {
            out.add(new HubEvent.Said(Level.INFO, "pair changes", "pair " + pair.first() + " - " + pair.second() + ": " + now.text()));
        }
    }

    /** A robot arrived: the state of its pairs seen before is recorded again (a kick forgot their breaks). */
    void arrived(String name, long nowNs, Changes out) {
        stats.pairsOf(name).forEach(pair -> record(pair, true, nowNs, out));
    }

    /** A robot left: its pairs' statistics count it gone from now. */
    void left(String name, long nowNs) {
        stats.left(name, nowNs);
    }

    /** A robot was kicked out: it left, and the model's breaks of its pairs are forgotten. */
    void kicked(String name, long nowNs) {
        left(name, nowNs);
        broken.removeIf(pair -> pair.contains(name));
    }

    /** The robot's ports were forgotten: so are the statistics and conditions of its pairs left without ports. */
    void forget(String name, Predicate<RobotPair> withoutPorts) {
        stats.forget(name, withoutPorts);
        conditions.forget(name, pair -> stats.get(pair) == null);
    }

    /**
     * The statistics of every pair seen; and of every pair of present robots an operator forced
     * before anything made it seen, fresh as of now (not kept): a forced pair is a pair the map,
     * the routes and the link statistics must show in its forced state, not as the model has it.
     */
    List<PairStats> stats(long nowNs) {
        List<PairStats> all = stats.all();
        for (RobotPair pair : forcedPairs.pairs()) {
            if (stats.get(pair) == null && bothPresent(pair)) {
                all.add(new PairStats(pair, stateOf(pair), true, nowNs));
            }
        }
        return all;
    }

    /** With links shaped: the pairs whose strength the hub asks the model for, a few times a second. */
    List<RobotPair> toMeasure() {
        return conditions.pairs();
    }

    /** What the model said of these pairs, each way: their rates follow. */
    void measured(Map<OrderedPair, Measurement> measurements, Changes out) {
        conditions.measured(measurements, out);
    }

    /** Every seen pair's condition one way, now. */
    Map<OrderedPair, PairCondition> conditions() {
        return conditions.now();
    }

    private boolean bothPresent(RobotPair pair) {
        return registered.test(pair.first()) && registered.test(pair.second());
    }
}
