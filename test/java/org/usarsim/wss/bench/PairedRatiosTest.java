package org.usarsim.wss.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class PairedRatiosTest {

    @Test
    void theMedianOfAnOddAndOfAnEvenNumberOfPairs() {
        assertEquals(0.97, new PairedRatios(new double[] {1.10, 0.85, 0.97}).median(), 1e-12);
        assertEquals(0.96, new PairedRatios(new double[] {1.10, 0.85, 0.97, 0.95}).median(), 1e-12);
    }

    @Test
    void theIntervalIsTheBinomialRulesOrderStatistics() {
        // n = 9: P(X <= 1) = 10/512 = 2.0 %, P(X <= 2) = 46/512 = 9.0 %: [x(2), x(8)], 96.1 % coverage.
        PairedRatios nine = new PairedRatios(new double[] {0.91, 0.99, 0.84, 1.07, 0.95, 1.02, 0.97, 0.93, 1.20});
        assertEquals(2, nine.intervalRank());
        assertArrayEquals(new double[] {0.91, 1.07}, nine.interval(), 1e-12);
        // n = 6 is the fewest with one: P(X = 0) = 1/64 = 1.6 %; n = 5: 1/32 = 3.1 %.
        assertEquals(1, new PairedRatios(new double[6]).intervalRank());
        assertNull(new PairedRatios(new double[5]).interval());
        // n = 25: P(X <= 7) = 2.16 %, P(X <= 8) = 5.39 %: [x(8), x(18)].
        assertEquals(8, new PairedRatios(new double[25]).intervalRank());
    }

    @Test
    void theSummaryNamesTheMedianTheIntervalAndTheRange() {
        String nine = new PairedRatios(new double[] {0.91, 0.99, 0.84, 1.07, 0.95, 1.02, 0.97, 0.93, 1.20}).summary();
        assertEquals("0.970x (95 % interval 0.910 to 1.070; 9 pairs from 0.84 to 1.20)", nine);
        assertTrue(new PairedRatios(new double[] {1, 1, 1}).summary().contains("too few pairs"));
    }
}
