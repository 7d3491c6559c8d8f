package org.usarsim.wss.hub.tcp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** wss.deadPeerSeconds: the keepalive timing chosen for a setting. */
class KeepAliveTimingTest {

    @Test
    void theTimingFitsTheSetting() {
        for (int seconds : new int[] {2, 3, 5, 10, 30, 31, 600, 86400}) {
            KeepAlive keepAlive = KeepAlive.within(seconds);
            assertTrue(keepAlive.idle >= 1 && keepAlive.interval >= 1 && keepAlive.count >= 1, keepAlive.toString());
            assertTrue(keepAlive.detectionSeconds() <= seconds, seconds + " s: " + keepAlive);
            assertTrue(keepAlive.idle <= 32767 && keepAlive.interval <= 32767 && keepAlive.count <= 127, keepAlive.toString());
        }
        KeepAlive thirty = KeepAlive.within(30);
        assertEquals(List.of(10, 5, 4), List.of(thirty.idle, thirty.interval, thirty.count));
        assertEquals(0, KeepAlive.within(0).detectionSeconds(), "0: the OS's timing");
        assertEquals(2, KeepAlive.within(1).detectionSeconds(), "1: the least keepalive can do, one idle second and one probe");
    }
}
