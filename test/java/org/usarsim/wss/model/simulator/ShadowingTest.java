package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import org.junit.jupiter.api.Test;

/** The shadowing field: off by default, deterministic, symmetric, sigma dB, correlated as Gudmundson's exp(-moved / distance). */
class ShadowingTest {

    private static ReportedRobot at(String name, double x, double y) {
        return new ReportedRobot(name, x, y, 0, false);
    }

    @Test
    void offByDefaultTheDeclaredDefaultsAddExactlyNothing() throws Exception {
        SimulatorConfig defaults = SimulatorConfig.read(SimulatorSettings.ALL, Map.of());
        Shadowing none = Shadowing.of(defaults.values());
        assertSame(Shadowing.NONE, none);
        double strength = defaults.pathLoss().strength(7.3);
        assertEquals(Double.doubleToLongBits(strength), Double.doubleToLongBits(strength + none.db(at("A", 0, 0), at("B", 7.3, 0))));
    }

    @Test
    void theSeedIsTheRunsWssSeedALongZeroWhenNotGiven() throws Exception {
        ReportedRobot a = at("A", 1, 2);
        ReportedRobot b = at("B", 30, -4);
        long big = 1L << 40;
        Shadowing seeded = Shadowing.of(SimulatorConfig.read(SimulatorSettings.ALL,
                Map.of("shadowing.sigma", "10", "wss.seed", String.valueOf(big))).values());
        assertEquals(new Shadowing(10, 5, big).db(a, b), seeded.db(a, b), "the run's wss.seed, read as a long");
        Shadowing unseeded = Shadowing.of(SimulatorConfig.read(SimulatorSettings.ALL, Map.of("shadowing.sigma", "10")).values());
        assertEquals(new Shadowing(10, 5, 0).db(a, b), unseeded.db(a, b), "the jitter's default, 0");
        assertTrue(SimulatorSettings.ALL.stream().noneMatch(setting -> setting.key().endsWith(".seed")), "no seed of the model's own");
    }

    @Test
    void theSameSeedAndPositionsGiveTheSameValuesWhicheverRobotIsFirst() throws Exception {
        assertEquals(8, Shadowing.of(SimulatorConfig.read(SimulatorSettings.ALL, Map.of("shadowing.sigma", "8")).values()).sigma());
        Shadowing one = new Shadowing(10, 5, 42);
        Shadowing two = new Shadowing(10, 5, 42);
        ReportedRobot a = at("A", 1, 2);
        ReportedRobot b = at("B", 30, -4);
        double value = one.db(a, b);
        assertEquals(value, two.db(a, b));
        assertEquals(value, one.db(b, a), "the pair's, not the order's");
        assertEquals(value, one.db(a, b), "standing still: no flicker");
        assertNotEquals(value, new Shadowing(10, 5, 43).db(a, b), "another seed, another field");
        assertNotEquals(value, one.db(a, at("C", 30, -4)), "another pair, another field");
    }

    @Test
    void itsValuesHaveSigmaAndTheirCorrelationFallsAsGudmundsonsExponential() {
        double sigma = 10;
        double distance = 5;
        int pairs = 4000;
        double[] moves = {0.5, 2, 5, 15};
        double sum = 0;
        double squares = 0;
        double[] products = new double[moves.length];
        for (int p = 0; p < pairs; p++) {
            Shadowing field = new Shadowing(sigma, distance, p);
            ReportedRobot a = at("A", 3, 4);
            ReportedRobot b = at("B", 20, 10);
            double here = field.db(a, b);
            sum += here;
            squares += here * here;
            for (int m = 0; m < moves.length; m++) {
                products[m] += here * field.db(a, at("B", 20 + moves[m], 10));
            }
        }
        double variance = squares / pairs;
        assertEquals(0, sum / pairs, 0.5, "mean");
        assertEquals(sigma, Math.sqrt(variance), 0.4, "sigma");
        for (int m = 0; m < moves.length; m++) {
            double correlation = products[m] / pairs / variance;
            assertEquals(Math.exp(-moves[m] / distance), correlation, 0.05, "correlation after " + moves[m] + " m");
        }
        assertTrue(Math.exp(-0.5 / distance) > 0.9, "two spots half a metre apart differ little");
    }
}
