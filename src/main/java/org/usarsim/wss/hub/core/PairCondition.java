package org.usarsim.wss.hub.core;

import org.usarsim.wss.model.DatagramLoss;

/**
 * A pair's condition one way, the one value the hub, the link threads, the statistics, the map
 * and the event log read: its state (up, broken, forced) and, when links are shaped, its rate
 * in bit/s and its delay in milliseconds (0 and 0 when they are not: as fast as the machine goes),
 * and the percent of datagrams a fixed UDP port loses (wss.shaping.loss; 0 unshaped), or the
 * model's own rule for them ({@link DatagramLoss}, the RFComms model's; null: the percent), and
 * the delay's jitter in milliseconds (wss.shaping.jitter or a pin's; 0: none).
 */
public record PairCondition(PairState state, long bitsPerSecond, int delayMs, double lossPercent, int jitterMs,
        DatagramLoss datagramLoss) {

    /** The datagrams lost by the percent. */
    public PairCondition(PairState state, long bitsPerSecond, int delayMs, double lossPercent, int jitterMs) {
        this(state, bitsPerSecond, delayMs, lossPercent, jitterMs, null);
    }

    /** No jitter. */
    public PairCondition(PairState state, long bitsPerSecond, int delayMs, double lossPercent) {
        this(state, bitsPerSecond, delayMs, lossPercent, 0);
    }

    /** No datagram lost. */
    public PairCondition(PairState state, long bitsPerSecond, int delayMs) {
        this(state, bitsPerSecond, delayMs, 0);
    }

    /** Whether anything passes: the pair is up, or forced up. */
    public boolean passes() {
        return state == PairState.UP || state == PairState.FORCED_UP;
    }

    /** Whether the link is shaped: it has a rate. */
    public boolean shaped() {
        return bitsPerSecond > 0;
    }
}
