package org.usarsim.wss.hub.core;

import java.util.Locale;

/** Where a pair of robots stands: as the model decides it, or as an operator forced it. */
public enum PairState {
    /** The model lets the pair talk. */
    UP,
    /** The model broke the pair (out of range, say). */
    BROKEN,
    /** An operator forced the pair down, whatever the model says. */
    FORCED_DOWN,
    /** An operator forced the pair up, whatever the model says. */
    FORCED_UP,
    /**
     * One of the two robots is not registered (it left, or was kicked): the pair cannot talk,
     * whatever it was. Only a snapshot says it; the core keeps the state it had.
     */
    GONE;

    /** How the window and the log say it: "up", "broken", "forced down", "forced up", "gone". */
    public String text() {
        return name().toLowerCase(Locale.ROOT).replace('_', ' ');
    }

    /** Whether the pair may talk in this state: up, by the model or forced. */
    public boolean isUp() {
        return this == UP || this == FORCED_UP;
    }

    /** Whether an operator forced the pair (down or up). */
    public boolean isForced() {
        return this == FORCED_DOWN || this == FORCED_UP;
    }
}
