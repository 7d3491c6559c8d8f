package org.usarsim.wss.hub.core;

/**
 * A pair's condition one way, the one value the hub, the link threads, the statistics, the map
 * and the event log read: its state (up, broken, forced) and, when links are shaped, its rate
 * in bit/s and its delay in milliseconds (0 and 0 when they are not: as fast as the machine goes).
 */
public record PairCondition(PairState state, long bitsPerSecond, int delayMs) {

    /** Whether the link is shaped: it has a rate. */
    public boolean shaped() {
        return bitsPerSecond > 0;
    }
}
