package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The jitter in a shaped TCP direction and a fixed UDP port's direction, on a clock the test
 * moves (docs/shaping.md, "Jitter"): a TCP chunk is due at the later of its own jittered time and
 * the chunk before it's, so bytes never overtake; datagrams keep their order unless reordering
 * is on, and then each goes at its own time.
 */
class JitterFlowTest {

    private static final long MS = 1_000_000;
    private static final long RATE = 1_000_000;
    /** 64 bytes at 1 Mbit/s. */
    private static final long AIRTIME_64 = 512_000;
    private static final int DELAY_MS = 50;
    private static final int JITTER_MS = 20;
    private static final long SEED = 99;

    @Test
    void aTcpChunkIsDueAtTheLaterOfItsOwnJitteredTimeAndThePreviousChunks() {
        ShapedFlow flow = new ShapedFlow(Airtime.unshared().open("A", "B", 0), RATE, DELAY_MS, JITTER_MS, ShapingConfig.DEFAULT_QUEUE_MS,
                JitterDistribution.NORMAL, SEED);
        // The same draws, one per grant, as the flow's own stage makes them.
        Delay delay = new Delay(DELAY_MS);
        Jitter draws = new Jitter(delay, JitterDistribution.NORMAL, SEED, JITTER_MS);
        int chunks = 40;
        long[] expected = new long[chunks];
        long previous = Long.MIN_VALUE;
        int overtakes = 0;
        for (int i = 0; i < chunks; i++) {
            long readAt = i * MS; // each chunk after the last one's grant ended: a grant of its own
            flow.accept(ByteBuffer.wrap(new byte[64]), readAt);
            long own = draws.dueAt(delay.dueAt(readAt + AIRTIME_64));
            overtakes += own < previous ? 1 : 0;
            expected[i] = Math.max(own, previous);
            previous = expected[i];
        }
        assertTrue(overtakes > 5, "the draws would reorder " + overtakes + " chunks: the rule is exercised");
        List<Long> releases = new ArrayList<>();
        long now = chunks * MS;
        long released = 0;
        while (released < 64L * chunks) {
            long due = flow.due(now);
            for (long b = released; b < due; b += 64) {
                releases.add(now);
            }
            released = due;
            now += flow.nanosUntilNext(now);
        }
        for (int i = 0; i < chunks; i++) {
            assertEquals(Math.max(expected[i], chunks * MS), releases.get(i), "chunk " + i);
        }
    }

    @Test
    void theJitterTakesItsPlaceInTheCapacityAndAChangeReachesTheBytesNotYetOnTheAir() {
        ShapedFlow flow = new ShapedFlow(Airtime.unshared().open("A", "B", 0), RATE, DELAY_MS, 0, ShapingConfig.DEFAULT_QUEUE_MS,
                JitterDistribution.UNIFORM, SEED);
        assertEquals(Bitrate.bytesIn((DELAY_MS + ShapingConfig.DEFAULT_QUEUE_MS) * MS, RATE), flow.capacity());
        flow.setConditions(RATE, DELAY_MS, JITTER_MS);
        assertEquals(JITTER_MS, flow.jitterMs());
        assertEquals(Bitrate.bytesIn((DELAY_MS + JITTER_MS + ShapingConfig.DEFAULT_QUEUE_MS) * MS, RATE), flow.capacity(),
                "uniform: at most the jitter more");
        flow.setConditions(2 * RATE, 10);
        assertEquals(JITTER_MS, flow.jitterMs(), "a new rate and delay keep the jitter");
    }

    private static List<Integer> sent(boolean reorder, List<Long> dueTimes) {
        DatagramFlow<Integer> flow = new DatagramFlow<>(Airtime.unshared().open("A", "B", 0), 1, JitterDistribution.UNIFORM, reorder, SEED);
        flow.setConditions(54_000_000, DELAY_MS, 0);
        flow.setJitterMs(JITTER_MS);
        List<Integer> order = new ArrayList<>();
        long now = 0;
        for (int i = 0; i < 200; i++) {
            now = i * MS;
            flow.offer(new byte[100], i, now);
            for (DatagramFlow.Datagram<Integer> datagram : flow.due(now)) {
                order.add(datagram.to());
                dueTimes.add(now);
            }
        }
        while (!flow.idle()) {
            now += flow.nanosUntilNext(now);
            for (DatagramFlow.Datagram<Integer> datagram : flow.due(now)) {
                order.add(datagram.to());
                dueTimes.add(now);
            }
        }
        return order;
    }

    @Test
    void withoutReorderingDatagramsKeepTheirOrderWhateverTheJitter() {
        List<Long> times = new ArrayList<>();
        List<Integer> order = sent(false, times);
        assertEquals(200, order.size());
        for (int i = 0; i < 200; i++) {
            assertEquals(i, order.get(i));
        }
    }

    @Test
    void withReorderingEachDatagramGoesAtItsOwnTimeSoLaterOnesOvertake() {
        List<Long> times = new ArrayList<>();
        List<Integer> order = sent(true, times);
        assertEquals(200, order.size());
        int overtaken = 0;
        for (int i = 1; i < order.size(); i++) {
            overtaken += order.get(i) < order.get(i - 1) ? 1 : 0;
            assertTrue(times.get(i) >= times.get(i - 1));
        }
        assertTrue(overtaken > 20, "a jitter of 20 ms on datagrams 1 ms apart reorders many: " + overtaken);
        // Each at its own time: off the air (100 bytes at 54 Mbit/s, 14.815 us after it is read) + 50 ms +- 20 ms.
        for (int i = 0; i < order.size(); i++) {
            long sentAfter = times.get(i) - order.get(i) * MS;
            assertTrue(sentAfter >= (DELAY_MS - JITTER_MS) * MS && sentAfter < (DELAY_MS + JITTER_MS) * MS + 20_000, "datagram " + order.get(i)
                    + " after " + sentAfter);
        }
    }
}
