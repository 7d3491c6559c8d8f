package org.usarsim.wss.hub.core;

/**
 * An operator's hand on a pair's shape ({@code FORCE ... {State Up} {Rate 1M} {Delay 50}}): a rate
 * in bit/s (0: not pinned, the rate table's) and a delay in milliseconds (-1: not pinned, the
 * setting's), both ways.
 */
public record RatePin(long bitsPerSecond, int delayMs) {

    /** Nothing pinned. */
    public static final RatePin NONE = new RatePin(0, -1);

    public boolean pinsRate() {
        return bitsPerSecond > 0;
    }

    public boolean pinsDelay() {
        return delayMs >= 0;
    }
}
