package org.usarsim.wss.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The replay's time as the time now moves: the test moves it, in milliseconds from an arbitrary origin. */
class ReplayClockTest {

    private static final long MS = 1_000_000L;
    private long now = 5_000 * MS;

    private long after(long millis) {
        now += millis * MS;
        return now;
    }

    @Test
    void playsAtItsSpeedFromTheStartOffset() {
        ReplayClock clock = new ReplayClock(60_000, false, 10_000, 1, now);
        assertEquals(10_000, clock.millis(now));
        assertTrue(clock.playing(now));
        assertEquals(10_500, clock.millis(after(500)));
        clock.speed(2, now);
        assertEquals(11_500, clock.millis(after(500)));
    }

    @Test
    void aSpeedChangeMidWayKeepsTheTimeContinuous() {
        ReplayClock clock = new ReplayClock(60_000, false, 0, 1, now);
        assertEquals(1_000, clock.millis(after(1_000)));
        clock.speed(8, now);
        assertEquals(1_000, clock.millis(now), "no jump at the change");
        assertEquals(9_000, clock.millis(after(1_000)));
        clock.speed(0.25, now);
        assertEquals(9_000, clock.millis(now));
        assertEquals(9_250, clock.millis(after(1_000)));
        assertEquals(0.25, clock.speed());
    }

    @Test
    void pauseHoldsTheTimeAndPlayGoesOnFromThere() {
        ReplayClock clock = new ReplayClock(60_000, false, 0, 2, now);
        clock.pause(after(1_000));
        assertEquals(2_000, clock.millis(now));
        assertFalse(clock.playing(now));
        assertEquals(2_000, clock.millis(after(30_000)), "held while paused");
        clock.speed(4, now);
        assertEquals(2_000, clock.millis(after(1_000)), "a speed change does not play");
        clock.play(now);
        assertEquals(6_000, clock.millis(after(1_000)));
    }

    @Test
    void aJumpSetsTheTimePlayingOrPaused() {
        ReplayClock clock = new ReplayClock(60_000, false, 0, 1, now);
        clock.jump(42_000, after(1_000));
        assertEquals(42_000, clock.millis(now));
        assertEquals(43_000, clock.millis(after(1_000)));
        clock.jump(500, now);
        assertEquals(500, clock.millis(now), "back as well as forth");
        clock.pause(now);
        clock.jump(30_000, after(5_000));
        assertEquals(30_000, clock.millis(after(5_000)), "paused stays paused");
        assertThrows(IllegalArgumentException.class, () -> clock.jump(60_001, now));
        assertThrows(IllegalArgumentException.class, () -> clock.jump(-1, now));
        assertThrows(IllegalArgumentException.class, () -> clock.jump(Double.NaN, now));
    }

    @Test
    void theEndStopsItPausedAndPlayStartsAgainFromZero() {
        ReplayClock clock = new ReplayClock(10_000, false, 9_000, 1, now);
        assertFalse(clock.atEnd(after(999)));
        assertTrue(clock.atEnd(after(1)));
        assertEquals(10_000, clock.millis(after(50_000)), "stays at the end");
        assertFalse(clock.playing(now));
        clock.jump(2_000, now);
        assertEquals(2_000, clock.millis(after(1_000)), "stopped at the end means paused: a jump does not play");
        clock.jump(10_000, now);
        clock.play(now);
        assertTrue(clock.playing(now));
        assertEquals(1_000, clock.millis(after(1_000)), "play at the end plays from the start");
    }

    @Test
    void loopWrapsToZero() {
        ReplayClock clock = new ReplayClock(10_000, true, 9_000, 1, now);
        assertEquals(9_999, clock.millis(after(999)));
        assertEquals(0, clock.millis(after(1)));
        assertEquals(500, clock.millis(after(500)));
        assertFalse(clock.atEnd(now));
        assertTrue(clock.playing(now));
        assertEquals(500, clock.millis(after(20_000)), "twice more round");
        clock.speed(2, now);
        assertEquals(2_500, clock.millis(after(1_000)));
    }

    @Test
    void aJumpToTheEndOfALoopReadsAsTheEndUntilTheTimeMovesOn() {
        ReplayClock clock = new ReplayClock(10_000, true, 0, 1, now);
        clock.jump(10_000, now);
        assertEquals(10_000, clock.millis(now), "REPLAY {Time 10} answers Time 10, not 0 (issue 26, item 7)");
        assertEquals(5, clock.millis(after(5)), "then it wraps and plays on");
    }

    @Test
    void nanosUntilATimeFollowTheSpeedAndPause() {
        ReplayClock clock = new ReplayClock(60_000, false, 0, 2, now);
        assertEquals(500 * MS, clock.nanosUntil(1_000, now));
        assertEquals(0, clock.nanosUntil(0, now));
        clock.pause(now);
        assertEquals(Long.MAX_VALUE, clock.nanosUntil(1_000, now));
    }

    @Test
    void aStartAtTheEndIsPausedThere() {
        ReplayClock clock = new ReplayClock(10_000, false, 10_000, 1, now);
        assertTrue(clock.atEnd(now));
        assertFalse(clock.playing(now));
        assertThrows(IllegalArgumentException.class, () -> new ReplayClock(10_000, false, 10_001, 1, now));
    }
}
