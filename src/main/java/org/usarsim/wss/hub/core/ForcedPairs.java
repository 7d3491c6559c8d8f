package org.usarsim.wss.hub.core;

import java.util.HashMap;
import java.util.Map;
import org.usarsim.wss.model.RobotPair;

/**
 * The pairs an operator forced down or up, and the rule that a forced state wins over the model's
 * verdict. A pair is forced by name, registered or not, and stays forced until released, through
 * robots leaving, coming back or being kicked out: an operator who forced "A:B down" meant it for
 * the run (docs/protocol.md section 7). Part of the core: single-threaded.
 */
final class ForcedPairs {

    private final Map<RobotPair, Force> forced = new HashMap<>();
    /** The rates and delays pinned with a force up. */
    private final Map<RobotPair, RatePin> pins = new HashMap<>();

    /** The pairs forced now. */
    java.util.Set<RobotPair> pairs() {
        return forced.keySet();
    }

    /** The pair's forced state, or null when the model decides it. */
    Force of(RobotPair pair) {
        return forced.get(pair);
    }

    /** Forces the pair; returns its forced state before (null: the model decided it). */
    Force force(RobotPair pair, Force force) {
        return forced.put(pair, force);
    }

    /** Gives the pair back to the model, its rate and delay too; returns its forced state before (null: it was not forced). */
    Force release(RobotPair pair) {
        pins.remove(pair);
        return forced.remove(pair);
    }

    /** Pins the pair's rate and delay (or unpins them, {@link RatePin#NONE}). @return whether that changed them */
    boolean pin(RobotPair pair, RatePin pin) {
        RatePin before = pin.equals(RatePin.NONE) ? pins.remove(pair) : pins.put(pair, pin);
        return !pin.equals(before == null ? RatePin.NONE : before);
    }

    /** The pair's pinned rate and delay, {@link RatePin#NONE} when none. */
    RatePin pinOf(RobotPair pair) {
        return pins.getOrDefault(pair, RatePin.NONE);
    }

    /**
     * The rule: whether the pair may talk (its ports listen, its connections are forwarded).
     * Forced up: yes, forced down: no, whatever the model says; otherwise the model's verdict.
     */
    boolean allows(RobotPair pair, boolean modelVerdict) {
        Force force = forced.get(pair);
        return force == null ? modelVerdict : force == Force.UP;
    }
}
