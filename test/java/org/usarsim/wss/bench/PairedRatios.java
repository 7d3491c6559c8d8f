package org.usarsim.wss.bench;

import java.util.Arrays;
import java.util.Locale;

/**
 * The ratios of paired runs (one ratio per pair, the two runs of a pair next to each other in
 * time): their median and a 95 % interval for it that assumes nothing of their distribution, from
 * the order statistics (the binomial rule: with n pairs the interval is [x(k), x(n+1-k)], k the
 * largest with P(Binomial(n, 1/2) &lt; k) &le; 2.5 %). Whether a ratio is above a target can be
 * said only when the interval is: 9 pairs give [x(2), x(8)], 5 pairs too few for any interval.
 */
final class PairedRatios {

    private final double[] sorted;

    PairedRatios(double[] ratios) {
        this.sorted = ratios.clone();
        Arrays.sort(sorted);
    }

    double median() {
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }

    /** k of the 95 % interval [x(k), x(n+1-k)] (1-based); 0 when there are too few pairs for one (fewer than 6). */
    int intervalRank() {
        int n = sorted.length;
        int k = 0;
        double below = 0; // P(X < k + 1) for X ~ Binomial(n, 1/2), adding P(X = k) as k grows
        for (int i = 0; i <= n / 2; i++) {
            below += binomialHalf(n, i);
            if (below > 0.025) {
                break;
            }
            k = i + 1;
        }
        return k;
    }

    /** The interval's ends {low, high}; null when there are too few pairs. */
    double[] interval() {
        int k = intervalRank();
        return k == 0 ? null : new double[] {sorted[k - 1], sorted[sorted.length - k]};
    }

    /** As the benchmark prints it: "0.97x (95 % interval 0.93 to 1.01; 9 pairs from 0.85 to 1.10)". */
    String summary() {
        double[] interval = interval();
        String range = interval == null ? "too few pairs for a 95 % interval"
                : String.format(Locale.ROOT, "95 %% interval %.3f to %.3f", interval[0], interval[1]);
        return String.format(Locale.ROOT, "%.3fx (%s; %d pairs from %.2f to %.2f)", median(), range, sorted.length, sorted[0],
                sorted[sorted.length - 1]);
    }

    /** P(X = i) for X ~ Binomial(n, 1/2). */
    private static double binomialHalf(int n, int i) {
        double choose = 1;
        for (int j = 1; j <= i; j++) {
            choose = choose * (n - i + j) / j;
        }
        return choose / Math.pow(2, n);
    }
}
