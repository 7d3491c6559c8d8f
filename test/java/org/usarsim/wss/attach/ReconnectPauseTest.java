package org.usarsim.wss.attach;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class ReconnectPauseTest {

    @Test
    void thePauseDoublesFromHalfASecondToTenSeconds() {
        ReconnectPause pause = new ReconnectPause();
        long now = 1_000;
        long[] expected = {500, 1_000, 2_000, 4_000, 8_000, 10_000, 10_000};
        for (long ms : expected) {
            long retryAt = pause.lost(now);
            assertEquals(now + ms, retryAt);
            now = retryAt; // the retry fails at once
        }
    }

    @Test
    void aConnectionThatWorkedStartsOverAtTheFirstPause() {
        ReconnectPause pause = new ReconnectPause();
        pause.lost(0);
        pause.lost(500);
        pause.connected();
        assertEquals(0, pause.pauseMs());
        assertEquals(5_500, pause.lost(5_000));
    }

    @Test
    void theSecondsLeftAreRoundedUpAndNeverBelowZero() {
        ReconnectPause pause = new ReconnectPause();
        pause.lost(0);
        pause.lost(0);
        pause.lost(0); // 2 s
        assertEquals(2, pause.secondsLeft(0));
        assertEquals(1, pause.secondsLeft(1_001));
        assertEquals(0, pause.secondsLeft(2_000));
        assertEquals(0, pause.secondsLeft(9_000));
    }
}
