package org.usarsim.wss.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** When the state is compared and counts told (the clock moved by hand). */
class CadenceTest {

    private static final long MS = 1_000_000;

    @Test
    void aChangeIsComparedWithin100MsAndCountsAtMostOnceASecond() {
        Cadence cadence = new Cadence();
        assertTrue(cadence.due(0, false), "the first at once");
        assertTrue(cadence.compared(0));
        assertEquals(1000 * MS, cadence.waitNs(0, false));
        assertEquals(100 * MS, cadence.waitNs(0, true));
        assertFalse(cadence.due(99 * MS, true));
        assertTrue(cadence.due(100 * MS, true));
        assertFalse(cadence.compared(100 * MS), "no counts 100 ms after the last");
        assertTrue(cadence.due(1100 * MS, false));
        assertTrue(cadence.compared(1100 * MS));
    }

    @Test
    void theHistoryIsRecordedUntilAMinuteAfterTheLastStream() {
        Cadence cadence = new Cadence();
        assertFalse(cadence.recording(0, false, false));
        cadence.streaming(5 * MS);
        assertTrue(cadence.recording(5 * MS + Cadence.LINGER_NS - 1, false, true));
        assertFalse(cadence.recording(5 * MS + Cadence.LINGER_NS, false, true));
    }

    @Test
    void withNoLingerItRecordsWhileAStreamIsOpenAndStopsAtOnceAfter() {
        Cadence cadence = new Cadence(0);
        cadence.streaming(5 * MS);
        assertTrue(cadence.recording(5 * MS, true, true), "a stream open at this very instant");
        assertTrue(cadence.recording(9 * MS, true, true));
        assertFalse(cadence.recording(9 * MS, false, true));
    }
}
