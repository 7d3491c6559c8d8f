package org.usarsim.wss.hub.core;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.RobotPair;

/** The throughput sampling of {@link PairStats}, at given instants (a reader's timer is never exact). */
class PairStatsTest {

    private static final long SECOND = TimeUnit.SECONDS.toNanos(1);

    @Test
    void aReadingEverySecondGivesEverySecondsThroughputThoughTheTimerRunsALittleEarly() {
        long start = 1_000 * SECOND;
        PairStats stats = new PairStats(RobotPair.of("A", "B"), PairState.UP, true, start);
        stats.bytesFrom("A").add(1_000_000);
        assertEquals(1_000_000, stats.rates(start + SECOND)[0], 1e-6, "the first second, counted from first seen");
        stats.bytesFrom("A").add(490_000); // wss.statsInterval = 1: the next reading comes 0.98 s later
        assertEquals(500_000, stats.rates(start + SECOND + SECOND * 98 / 100)[0], 1e-6, "the second second's own rate");
        // The traffic stopped: the next reading says so, not the rate of before.
        assertEquals(0, stats.rates(start + 2 * SECOND + SECOND * 97 / 100)[0], 1e-6);
        assertEquals(0, stats.rates(start + 3 * SECOND)[1], 1e-6, "nothing B -> A");
    }

    @Test
    void timeUpCountsOnlyWhileBothRobotsAreRegistered() {
        long start = 1_000 * SECOND;
        PairStats stats = new PairStats(RobotPair.of("A", "B"), PairState.UP, true, start);
        assertEquals(1.0, stats.upShare(start + SECOND), 1e-9, "up, both there");
        stats.absent(start + SECOND); // B leaves for 2 s
        assertEquals(PairState.UP, stats.state(), "the state shown stays");
        assertEquals(1.0 / 3, stats.upShare(start + 3 * SECOND), 1e-9, "B's absence is not time up");
        assertEquals(false, stats.moveTo(PairState.UP, true, start + 3 * SECOND), "B back: no state change to say");
        assertEquals(2.0 / 4, stats.upShare(start + 4 * SECOND), 1e-9, "up again since B came back");
        assertEquals(true, stats.moveTo(PairState.BROKEN, true, start + 4 * SECOND));
        assertEquals(2.0 / 5, stats.upShare(start + 5 * SECOND), 1e-9, "broken is not up");
    }

    @Test
    void aPairSeenWithARobotMissingIsNotUpUntilItComes() {
        long start = 1_000 * SECOND;
        PairStats stats = new PairStats(RobotPair.of("A", "B"), PairState.FORCED_UP, false, start); // forced ahead of time
        assertEquals(0.0, stats.upShare(start), 1e-9);
        assertEquals(false, stats.moveTo(PairState.FORCED_UP, true, start + SECOND));
        assertEquals(0.5, stats.upShare(start + 2 * SECOND), 1e-9);
    }
}
