package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.hub.core.UdpCounts;

/** The Link statistics' UDP column: sent/dropped broken/dropped by the queue/lost, each way; empty without UDP. */
class UdpColumnTest {

    private static PairEntry pair(UdpCounts.Reading ab, UdpCounts.Reading ba) {
        return new PairEntry("A", "B", PairState.UP, -60, 5, 0, 0, 0, 0, 0, 0, 0, 1, null, 0, 0, ab, ba);
    }

    @Test
    void eachWayItsFourCountsAndNothingForAPairWithoutUdp() {
        assertEquals("", StatsPanel.udp(pair(UdpCounts.Reading.NONE, UdpCounts.Reading.NONE)));
        assertEquals("120/1/3/12 | 0/0/0/0",
                StatsPanel.udp(pair(new UdpCounts.Reading(120, 120_000, 1, 3, 12), UdpCounts.Reading.NONE)));
    }
}
