package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** One direction of a fixed UDP port on a moved clock: rate, delay, the queue's bound and the loss, with a fixed seed. */
class DatagramFlowTest {

    private static final long MS = 1_000_000L;

    private static DatagramFlow<String> flow(long seed) {
        return new DatagramFlow<>(Airtime.shared().open("A", "B", 0), seed);
    }

    @Test
    void unshapedADatagramIsDueAtOnceWholeAndInOrder() {
        DatagramFlow<String> flow = flow(1);
        flow.setConditions(0, 0, 0);
        byte[] largest = new byte[DatagramFlow.MAX_DATAGRAM];
        largest[DatagramFlow.MAX_DATAGRAM - 1] = 7;
        assertTrue(flow.offer(largest, "s1", 5));
        assertTrue(flow.offer(new byte[0], "s2", 5));
        List<DatagramFlow.Datagram<String>> due = flow.due(5);
        assertEquals(2, due.size());
        assertEquals(DatagramFlow.MAX_DATAGRAM, due.get(0).data().length);
        assertEquals(7, due.get(0).data()[DatagramFlow.MAX_DATAGRAM - 1]);
        assertEquals("s1", due.get(0).to());
        assertEquals("s2", due.get(1).to());
        assertTrue(flow.idle());
        assertEquals(Long.MAX_VALUE, flow.nanosUntilNext(5));
    }

    @Test
    void shapedADatagramIsDueAfterItsAirtimeAndTheDelay() {
        DatagramFlow<String> flow = flow(1);
        flow.setConditions(8_000_000, 2, 0); // 1 byte a microsecond
        flow.offer(new byte[1000], "s", 0); // 1 ms on the air
        flow.offer(new byte[1000], "s", 0); // the next 1 ms
        assertEquals(3 * MS, flow.nanosUntilNext(0));
        assertEquals(List.of(), flow.due(3 * MS - 1));
        assertEquals(1, flow.due(3 * MS).size());
        assertEquals(1 * MS, flow.nanosUntilNext(3 * MS));
        assertEquals(1, flow.due(4 * MS).size());
        assertTrue(flow.idle());
    }

    @Test
    void aFullQueueDropsTheTailAndCountsIt() {
        long rate = 8_000_000;
        DatagramFlow<String> flow = flow(1);
        flow.setConditions(rate, 0, 0);
        long capacity = DatagramFlow.capacity(rate); // 100 ms at 1 MB/s + 65,507
        assertEquals(100_000 + 65_507, capacity);
        int accepted = 0;
        for (int i = 0; i < 200; i++) {
            if (flow.offer(new byte[1000], "s", 0)) {
                accepted++;
            }
        }
        // a few are booked on the air at once (within the lookahead), the rest fill the queue to its bound
        assertTrue(accepted >= 165 && accepted <= 175, "accepted " + accepted);
        assertEquals(200 - accepted, flow.droppedQueue());
        assertFalse(flow.offer(new byte[1000], "s", 0));
        // a second later all that was accepted has gone, and the queue takes more
        long delivered = 0;
        for (long t = 0; t <= 1000 * MS; t += MS) {
            delivered += flow.due(t).size();
        }
        assertEquals(accepted, delivered);
        assertTrue(flow.offer(new byte[1000], "s", 1000 * MS));
    }

    @Test
    void theLossIsDrawnAsADatagramLeavesTheQueueAndALostOneStillTakesItsAirtime() {
        DatagramFlow<String> flow = flow(42);
        flow.setConditions(80_000_000, 0, 10); // 100 bytes take 10 us
        int sent = 0;
        long t = 0;
        for (int i = 0; i < 100_000; i++) {
            flow.offer(new byte[100], "s", t);
            t += 10_000; // as fast as the rate
            sent += flow.due(t).size();
        }
        sent += flow.due(t + MS).size();
        assertEquals(100_000, sent + flow.lost());
        assertEquals(10.0, flow.lost() / 1000.0, 0.5, "percent lost");
        assertEquals(0, flow.droppedQueue());
        // the same seed loses the same datagrams
        List<Integer> lostFirst = lostOf(flow(42));
        assertTrue(lostFirst.size() > 0 && lostFirst.size() < 20, "some lost: " + lostFirst);
        assertEquals(lostFirst, lostOf(flow(42)));
    }

    @Test
    void aModelsLossRuleDecidesInsteadOfThePercentWithTheSizeTheTimeAndTheFlowsGenerator() {
        DatagramFlow<String> flow = flow(5);
        flow.setConditions(80_000_000, 0, 100); // the percent would lose everything
        List<Long> asked = new ArrayList<>();
        flow.setLossRule((bytes, nowNs, random) -> {
            asked.add(nowNs);
            return bytes > 100;
        });
        flow.offer(new byte[100], "kept", 0);
        flow.offer(new byte[101], "lost", 0);
        flow.offer(new byte[50], "kept too", 0);
        List<String> due = new ArrayList<>();
        flow.due(MS).forEach(datagram -> due.add(datagram.to()));
        assertEquals(List.of("kept", "kept too"), due);
        assertEquals(1, flow.lost());
        assertEquals(List.of(0L, 0L, 0L), asked, "asked once per datagram, as it goes on the air");
        flow.setLossRule(null);
        flow.offer(new byte[10], "the percent again", 2 * MS);
        assertTrue(flow.due(3 * MS).isEmpty());
        assertEquals(2, flow.lost());
    }

    @Test
    void aLostDatagramKeepsTheRadioBusy() {
        Airtime air = Airtime.shared();
        DatagramFlow<String> lossy = new DatagramFlow<>(air.open("A", "B", 0), 1);
        lossy.setConditions(8_000_000, 0, 100); // everything lost
        lossy.offer(new byte[1000], "s", 0);
        assertEquals(List.of(), lossy.due(10 * MS));
        assertEquals(1, lossy.lost());
        // the radio was still on the air for 1 ms: another hop on A starts after it
        Airtime.Grant next = air.open("A", "C", 0).grant(1, 0);
        assertEquals(MS, next.startNs());
    }

    /** The indexes of the datagrams a 50 % loss drops out of 20. */
    private static List<Integer> lostOf(DatagramFlow<String> flow) {
        flow.setConditions(80_000_000, 0, 50);
        List<Integer> lost = new ArrayList<>();
        for (int i = 0; i < 20; i++) {
            long before = flow.lost();
            flow.offer(new byte[10], "s" + i, i * MS);
            flow.due(i * MS);
            if (flow.lost() > before) {
                lost.add(i);
            }
        }
        return lost;
    }
}
