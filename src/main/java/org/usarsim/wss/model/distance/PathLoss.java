package org.usarsim.wss.model.distance;

/**
 * The log-distance path loss of the original: S = Pd0 - 10 N log10(d / d0) dBm at d metres; a pair
 * may connect while S is at least the cutoff.
 */
public record PathLoss(double pd0, double n, double d0, double cutoff) {

    /** The strength at {@code metres}; +Infinity at 0 m. */
    public double strength(double metres) {
        return pd0 - 10 * n * Math.log10(metres / d0);
    }

    /** The distance at which the strength falls to the cutoff. */
    public double range() {
        return d0 * Math.pow(10, (pd0 - cutoff) / (10 * n));
    }
}
