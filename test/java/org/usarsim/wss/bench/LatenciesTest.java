package org.usarsim.wss.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class LatenciesTest {

    private static Latencies of(long... ms) {
        Latencies latencies = new Latencies();
        for (long each : ms) {
            latencies.add(each * 1_000_000, each * 1_000_000 + 500_000);
        }
        return latencies;
    }

    @Test
    void theBoundsAreIssue31s() {
        assertEquals(120, Latencies.medianBound(200), 1e-12);
        assertEquals(250, Latencies.p99Bound(200), 1e-12);
        assertEquals(70, Latencies.medianBound(100), 1e-12);
        assertEquals(150, Latencies.p99Bound(100), 1e-12);
    }

    @Test
    void aFigureOnItsBoundPassesAndOneAboveFails() {
        assertEquals("publish -> GETSS median 120.0 ms PASS, p99 250.0 ms PASS; -> break/resume median 120.5 ms, p99 250.5 ms;"
                + " 3 moves", of(10, 120, 250).line(200));
        assertEquals("publish -> GETSS median 121.0 ms FAIL, p99 251.0 ms FAIL; -> break/resume median 121.5 ms, p99 251.5 ms;"
                + " 3 moves", of(10, 121, 251).line(200));
    }

    @Test
    void missedMovesAndSilencesAreSaid() {
        Latencies latencies = of(50);
        latencies.missed();
        latencies.silences(2);
        assertTrue(latencies.line(100).endsWith("1 moves, 1 missed, 2 silences said"), latencies.line(100));
    }
}
