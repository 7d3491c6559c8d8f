package org.usarsim.wss.model.rfcomms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** RFComms' 1 s window: capacity x 1 s bits, a message refused once it would exceed them, the old ones leaving after 1 s. */
class CapacityWindowTest {

    private static final long S = 1_000_000_000L;

    @Test
    void fiftyFourMegabitsHoldFourThousandFiveHundredMessagesOf1500BytesASecond() {
        CapacityWindow window = new CapacityWindow(54e6);
        int admitted = 0;
        while (window.admit(0, 1500)) {
            admitted++;
        }
        assertEquals((int) (54e6 / 8 / 1500), admitted);
        assertFalse(window.admit(S, 1500), "still in the window at exactly 1 s: RFComms drops only older ones");
        assertTrue(window.admit(S + 1, 1500), "older than 1 s: gone");
        assertEquals(1500, window.bytes());
    }

    @Test
    void aRefusedMessageIsNotCountedAndASmallerOneMayStillFit() {
        CapacityWindow window = new CapacityWindow(8000); // 1000 bytes a second
        assertTrue(window.admit(0, 900));
        assertFalse(window.admit(1, 200));
        assertTrue(window.admit(2, 100));
        assertEquals(1000, window.bytes());
    }
}
