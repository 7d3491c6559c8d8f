package org.usarsim.wss.gui;

import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.RatePin;

/**
 * An operator's hand on a pair of robots, as the {@link ForceMenu} uses it: a server the window
 * runs ({@link Servers.Running}) or one it is attached to with an operator's token. Slow (a lock,
 * or the network): never on the event thread.
 */
public interface PairControls {

    /** Forces the pair down or up until {@link #release}. */
    default void force(String robotA, String robotB, Force force) {
        force(robotA, robotB, force, RatePin.NONE);
    }

    /**
     * As {@link #force(String, String, Force)}, up with the pair's rate and delay pinned
     * ({@link RatePin#NONE}: nothing pinned), as {@code FORCE ... {Rate r} {Delay d}} does
     * (docs/shaping.md).
     */
    void force(String robotA, String robotB, Force force, RatePin pin);

    /** Gives the pair back to the model. */
    void release(String robotA, String robotB);
}
