package org.usarsim.wss.shaping;

/**
 * The standard normal distribution's quantile (its inverse CDF), for {@link JitterDistribution}:
 * a table of the CDF over [-5, 5] in steps of 1/2048, computed once by Simpson's rule on the
 * density, and inverted by bisection and linear interpolation. Accurate to about 1e-6 in
 * probability; beyond the table, +-5 (the jitter clamps at 4 anyway).
 */
final class NormalQuantile {

    private static final double LOW = -5;
    private static final int STEPS_PER_UNIT = 2048;
    private static final int SIZE = 10 * STEPS_PER_UNIT + 1;
    private static final double[] CDF = new double[SIZE];

    static {
        double h = 1.0 / STEPS_PER_UNIT;
        double below = 2.866515718791939e-7; // Phi(-5)
        CDF[0] = below;
        for (int i = 1; i < SIZE; i++) {
            double a = LOW + (i - 1) * h;
            double b = a + h;
            below += h / 6 * (density(a) + 4 * density((a + b) / 2) + density(b));
            CDF[i] = below;
        }
    }

    private NormalQuantile() {
    }

    private static double density(double x) {
        return Math.exp(-x * x / 2) / Math.sqrt(2 * Math.PI);
    }

    /** The x with Phi(x) = {@code p}, p in [0, 1]. */
    static double at(double p) {
        if (p <= CDF[0]) {
            return LOW;
        }
        if (p >= CDF[SIZE - 1]) {
            return -LOW;
        }
        int lo = 0;
        int hi = SIZE - 1;
        while (hi - lo > 1) {
            int mid = (lo + hi) >>> 1;
            if (CDF[mid] <= p) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        double share = (p - CDF[lo]) / (CDF[hi] - CDF[lo]);
        return LOW + (lo + share) / STEPS_PER_UNIT;
    }
}
