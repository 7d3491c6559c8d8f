package org.usarsim.wss.routes;

/**
 * One way of a pair that is up now, as a route may use it: from, to, the model's strength (dBm,
 * NaN unknown) and, with links shaped, the pair's rate that way (bit/s; 0 unshaped).
 */
public record Hop(String from, String to, double strength, long bitsPerSecond) {

    @Override
    public String toString() {
        return from + "," + to;
    }
}
