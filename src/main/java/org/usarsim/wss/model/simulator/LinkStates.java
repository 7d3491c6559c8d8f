package org.usarsim.wss.model.simulator;

import java.util.Collection;
import java.util.HashMap;
import java.util.Map;
import org.usarsim.wss.model.RobotPair;

/**
 * Whether each pair's link is up, decided from its strength at every poll. A live link goes down
 * when the strength falls below the cutoff; a broken link comes up only at cutoff + margin or more;
 * and once changed, a state holds at least the hold time. With margin 0 and hold time 0 this is the
 * original's rule: up exactly while the strength is at least the cutoff. Used by one thread at a
 * time: a poll decides on a {@link #copy}, and publishes it once decided.
 */
final class LinkStates {

    private record State(boolean live, long sinceNanos) {
    }

    private final double cutoff;
    private final double margin;
    private final long holdNanos;
    private final Map<RobotPair, State> states = new HashMap<>();

    LinkStates(double cutoff, double margin, double holdSeconds) {
        this(cutoff, margin, (long) (holdSeconds * 1e9), Map.of());
    }

    private LinkStates(double cutoff, double margin, long holdNanos, Map<RobotPair, State> states) {
        this.cutoff = cutoff;
        this.margin = margin;
        this.holdNanos = holdNanos;
        this.states.putAll(states);
    }

    /** The same rule and states, to decide on while this one stays as it is. */
    LinkStates copy() {
        return new LinkStates(cutoff, margin, holdNanos, states);
    }

    /** Decides the pair's state for the strength measured at {@code nowNanos}; NaN counts as out of range. */
    boolean decide(RobotPair pair, double strength, long nowNanos) {
        State state = states.get(pair);
        if (state == null) {
            state = new State(strength >= cutoff, nowNanos);
            states.put(pair, state);
            return state.live();
        }
        boolean wanted = state.live() ? strength >= cutoff : strength >= cutoff + margin;
        if (wanted != state.live() && nowNanos - state.sinceNanos() >= holdNanos) {
            state = new State(wanted, nowNanos);
            states.put(pair, state);
        }
        return state.live();
    }

    /** The pair's decided state: TRUE or FALSE, or null when it was never decided. */
    Boolean live(RobotPair pair) {
        State state = states.get(pair);
        return state == null ? null : state.live();
    }

    /** Forgets every pair with a robot not in {@code robots} (it left; a return starts afresh). */
    void retainOnly(Collection<String> robots) {
        states.keySet().removeIf(pair -> !robots.contains(pair.first()) || !robots.contains(pair.second()));
    }
}
