package org.usarsim.wss.model.simulator;

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
        return range(0);
    }

    /**
     * The distance at which the strength, less {@code lossDb} (the walls between, say), falls to the
     * cutoff; below d0 when the loss alone takes it there, and 0 for an infinite loss.
     */
    public double range(double lossDb) {
        return d0 * Math.pow(10, (pd0 - lossDb - cutoff) / (10 * n));
    }

    /**
     * The inverse of {@link #range()}: the N that gives this range, (pd0 - cutoff) / (10 log10(range
     * / d0)). NaN when no N above 0 does: when the range is on the wrong side of d0 (beyond it needs
     * a cutoff below pd0, within it a cutoff above), when it is d0 itself (that range comes with any
     * N when cutoff = pd0, with none otherwise), or when the N would not be a finite double.
     */
    public static double exponentFor(double pd0, double d0, double cutoff, double range) {
        double n = (pd0 - cutoff) / (10 * Math.log10(range / d0));
        return n > 0 && Double.isFinite(n) ? n : Double.NaN;
    }
}
