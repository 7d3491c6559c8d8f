package org.usarsim.wss.hub.core;

/**
 * An operator's hand on a pair's shape ({@code FORCE ... {State Up} {Rate 1M} {Delay 50} {Jitter 20}}):
 * a rate in bit/s (0: not pinned, the rate table's), a delay in milliseconds (-1: not pinned, the
 * setting's) and the delay's jitter in milliseconds (-1: not pinned, wss.shaping.jitter), both ways.
 */
public record RatePin(long bitsPerSecond, int delayMs, int jitterMs) {

    /** Nothing pinned. */
    public static final RatePin NONE = new RatePin(0, -1, -1);

    /** The jitter not pinned. */
    public RatePin(long bitsPerSecond, int delayMs) {
        this(bitsPerSecond, delayMs, -1);
    }

    public boolean pinsJitter() {
        return jitterMs >= 0;
    }

    public boolean pinsRate() {
        return bitsPerSecond > 0;
    }

    public boolean pinsDelay() {
        return delayMs >= 0;
    }
}
