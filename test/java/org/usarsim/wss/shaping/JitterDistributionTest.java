package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The jitter's samplers (docs/shaping.md, "Jitter"): mean, standard deviation and bounds of
 * 200,000 draws with a fixed seed, against the values the definitions give in closed form
 * (deterministic: the same seed draws the same numbers; the tolerances are some 5 standard
 * errors of each estimate).
 */
class JitterDistributionTest {

    private static final int N = 200_000;

    /** Mean, standard deviation, least and largest of N draws, and the share below {@code below}. */
    private record Moments(double mean, double sd, double min, double max, double shareBelow) {
    }

    private static Moments draws(JitterDistribution distribution, double below) {
        SplittableRandom random = new SplittableRandom(42);
        double sum = 0;
        double squares = 0;
        double min = Double.MAX_VALUE;
        double max = -Double.MAX_VALUE;
        int under = 0;
        for (int i = 0; i < N; i++) {
            double z = distribution.draw(random);
            sum += z;
            squares += z * z;
            min = Math.min(min, z);
            max = Math.max(max, z);
            under += z < below ? 1 : 0;
        }
        double mean = sum / N;
        return new Moments(mean, Math.sqrt(squares / N - mean * mean), min, max, (double) under / N);
    }

    @Test
    void uniformIsDelayPlusOrMinusTheJitter() {
        Moments m = draws(JitterDistribution.UNIFORM, 0.5);
        assertEquals(0, m.mean(), 0.007);
        assertEquals(1 / Math.sqrt(3), m.sd(), 0.004);
        assertTrue(m.min() >= -1 && m.max() < 1, m.toString());
        assertEquals(0.75, m.shareBelow(), 0.005, "P(Z < 0.5) = 0.75");
    }

    @Test
    void normalIsTheStandardNormalWithinNetemsTableRange() {
        Moments m = draws(JitterDistribution.NORMAL, 1);
        assertEquals(0, m.mean(), 0.012);
        assertEquals(1, m.sd(), 0.008);
        assertTrue(m.min() >= -4 && m.max() <= 4, m.toString());
        assertEquals(0.841345, m.shareBelow(), 0.005, "Phi(1)");
        assertEquals(0.5, draws(JitterDistribution.NORMAL, 0).shareBelow(), 0.006);
    }

    @Test
    void normalQuantileInvertsPhi() {
        assertEquals(0, NormalQuantile.at(0.5), 1e-5);
        assertEquals(1, NormalQuantile.at(0.841344746), 1e-4);
        assertEquals(-1.959964, NormalQuantile.at(0.025), 1e-4);
        assertEquals(2.326348, NormalQuantile.at(0.99), 1e-4);
    }

    /**
     * Pareto as iproute2's table makes it: Z = 4/3 (X - 1.5), X Pareto of shape 3 and scale 1,
     * capped at Z = 4 (X = 4.5). With c = 4.5: E[min(X, c)] = 1.5 (1 - c^-2) + c^-2 and
     * E[min(X, c)^2] = 3 - 2 / c.
     */
    @Test
    void paretoIsNetemsShapeThreeParetoCentredAndCapped() {
        double c = 4.5;
        double mean = 1.5 * (1 - 1 / (c * c)) + 1 / (c * c);
        double sd = Math.sqrt(3 - 2 / c - mean * mean);
        Moments m = draws(JitterDistribution.PARETO, 0);
        assertEquals(4.0 / 3 * (mean - 1.5), m.mean(), 0.01, "-0.0329");
        assertEquals(4.0 / 3 * sd, m.sd(), 0.01, "0.8209");
        assertTrue(m.min() >= -2.0 / 3 && m.max() <= 4, m.toString());
        assertEquals(1 - Math.pow(1.5, -3), m.shareBelow(), 0.005, "P(X < 1.5) = 1 - 1.5^-3: Z below 0");
    }

    /** Paretonormal: (N(u) + 3 P(u)) / 4 at one u, so its mean is a quarter of the normal's and three quarters of the Pareto's. */
    @Test
    void paretonormalMixesAQuarterNormalAndThreeQuartersPareto() {
        double c = 4.5;
        double paretoMean = 4.0 / 3 * (1.5 * (1 - 1 / (c * c)) + 1 / (c * c) - 1.5);
        Moments m = draws(JitterDistribution.PARETONORMAL, 0);
        assertEquals(0.75 * paretoMean, m.mean(), 0.01);
        assertTrue(m.sd() > 0.75 && m.sd() <= (1 + 3 * 0.821) / 4 + 0.01, "at most the sum of the parts' (comonotone): " + m);
        assertTrue(m.min() >= -4 && m.max() <= 4, m.toString());
    }

    @Test
    void theSameSeedDrawsTheSameNumbers() {
        for (JitterDistribution distribution : JitterDistribution.values()) {
            SplittableRandom a = new SplittableRandom(7);
            SplittableRandom b = new SplittableRandom(7);
            for (int i = 0; i < 100; i++) {
                assertEquals(distribution.draw(a), distribution.draw(b));
            }
        }
    }

    @Test
    void namesAreNetems() {
        assertEquals(JitterDistribution.PARETONORMAL, JitterDistribution.of(" ParetoNormal "));
        assertEquals("uniform", JitterDistribution.UNIFORM.word());
        assertNull(JitterDistribution.of("gaussian"));
    }

    @Test
    void theJitterStageNeverLetsBytesGoBeforeTheyAreOffTheAirAndHoldsAtMostItsLargestDraw() {
        Delay delay = new Delay(5);
        Jitter jitter = new Jitter(delay, JitterDistribution.NORMAL, 3, 20);
        assertEquals(80_000_000, jitter.holdsNs(), "4 x 20 ms");
        long offAir = 1_000_000_000L;
        long sum = 0;
        for (int i = 0; i < 10_000; i++) {
            long due = jitter.dueAt(delay.dueAt(offAir));
            assertTrue(due >= offAir && due <= offAir + 5_000_000 + 80_000_000, "due " + (due - offAir));
            sum += due - offAir;
        }
        assertTrue(sum / 10_000 > 5_000_000, "truncated at 0, N(5, 20) averages more than 5 ms: " + sum / 10_000);
        Jitter none = new Jitter(delay, JitterDistribution.NORMAL, 3, 0);
        assertEquals(offAir + 5_000_000, none.dueAt(delay.dueAt(offAir)), "no jitter: the delay alone");
    }
}
