package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.Channels;
import java.util.Random;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.shaping.SimulatedLinks.Lane;

/** One shaped direction, and several sharing radios, on a clock the test moves: no sleeps, no threads. */
@Tag("slow")
class ShapedFlowTest {

    private static final long MS = 1_000_000;
    private static final long SECOND = 1_000_000_000;
    private static final int CHUNK = 4096;

    @Test
    void eachRateIsKeptWithinOnePercentOverTenSeconds() {
        for (long rate : new long[] {512_000, 1_000_000, 6_000_000, 11_000_000, 24_000_000, 54_000_000}) {
            SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, false);
            Lane lane = links.add("A", "B", rate, 2, CHUNK, SimulatedLinks.endless());
            links.runFor(10 * SECOND);
            double expected = rate * 10 / 8.0;
            assertEquals(expected, lane.delivered, expected / 100, Bitrate.format(rate));
            assertTrue(lane.delivered <= expected, Bitrate.format(rate) + ": never faster than the rate");
        }
    }

    @Test
    void aChunkIsDueAfterTheDelayAndItsTimeOnTheAir() throws IOException {
        long start = -1_000_000_000_000L; // nanoTime may be negative
        ShapedFlow flow = new ShapedFlow(Airtime.shared().open("A", "B", start), 1_000_000, 50, ShapingConfig.DEFAULT_QUEUE_MS);
        flow.accept(ByteBuffer.wrap(new byte[64]), start);
        long due = start + 50 * MS + 512_000; // 64 x 8 / 1 Mbit/s = 512 us
        assertEquals(0, flow.due(start));
        assertEquals(due - start, flow.nanosUntilNext(start));
        assertEquals(0, flow.due(due - 1));
        assertEquals(1, flow.nanosUntilNext(due - 1));
        ByteArrayOutputStream target = new ByteArrayOutputStream();
        assertEquals(0, flow.writeTo(Channels.newChannel(target), due - 1));
        assertEquals(64, flow.due(due));
        assertEquals(64, flow.writeTo(Channels.newChannel(target), due));
        assertEquals(64, target.size());
        assertEquals(0, flow.held());
        assertEquals(Long.MAX_VALUE, flow.nanosUntilNext(due), "nothing held, nothing scheduled");
    }

    @Test
    void twoPeersShareTheSendersAirtimeByTimeNotByBytes() {
        long fast = 24_000_000;
        long slow = fast / 4;
        SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, false);
        Lane near = links.add("A", "B", fast, 2, CHUNK, SimulatedLinks.endless());
        Lane far = links.add("A", "C", slow, 2, CHUNK, SimulatedLinks.endless());
        links.runFor(10 * SECOND);
        double nearShare = near.delivered * 8.0 / fast / 10;
        double farShare = far.delivered * 8.0 / slow / 10;
        assertEquals(0.5, nearShare, 0.05, "the near link's airtime");
        assertEquals(0.5, farShare, 0.05, "the far link's airtime");
        assertEquals(1, nearShare + farShare, 0.03, "together, all of A's airtime");
        assertEquals(1, links.airtime.inUse("A", links.now), 0.03, "A's airtime in use");
        assertEquals(0.25, far.delivered / (double) near.delivered, 0.0125, "the far link moves a quarter of the near one's bytes");
    }

    @Test
    void aLinkAtAnyRateFrom1BitPerSecondTakesHalfTheRadioBeside54MbitPerSecond() {
        long fast = 54_000_000;
        for (long slow : new long[] {1, 100, 1_000, 4_000, 64_000, 1_000_000, fast}) {
            long seconds = slow < 100 ? 400 : 20; // at 1 bit/s half the airtime is a byte every 16 s
            SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, false);
            Lane pinned = links.add("A", "B", slow, 2, CHUNK, SimulatedLinks.endless());
            Lane near = links.add("A", "C", fast, 2, CHUNK, SimulatedLinks.endless());
            links.runFor(seconds * SECOND);
            double pinnedShare = pinned.delivered * 8.0 / slow / seconds;
            double nearShare = near.delivered * 8.0 / fast / seconds;
            String at = Bitrate.format(slow) + " beside 54 Mbit/s";
            assertEquals(0.5, pinnedShare, 0.05, at + ": the pinned link's airtime");
            assertEquals(0.5, nearShare, 0.05, at + ": the 54 Mbit/s link's airtime");
            assertEquals(1, links.airtime.inUse("A", links.now), 0.03, at + ": A's airtime in use");
        }
    }

    @Test
    void aByteAt1BitPerSecondIsCarriedOverManyGrantsAndIsNeverEarly() {
        SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, true);
        Lane lane = links.add("A", "B", 1, 2, CHUNK, SimulatedLinks.finite(1));
        links.runUntil(8 * SECOND + 2 * MS - 1);
        assertEquals(0, lane.delivered, "8 s on the air and 2 ms of delay are not over");
        links.runUntil(8 * SECOND + 2 * MS);
        assertEquals(1, lane.delivered);
    }

    @Test
    void aRateRaisedReachesTheLinkWithinItsTurnAndTheDelay() {
        long fast = 54_000_000;
        int delayMs = 2;
        SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, false);
        Lane pinned = links.add("A", "B", 1, delayMs, CHUNK, SimulatedLinks.endless());
        Lane near = links.add("A", "C", fast, delayMs, CHUNK, SimulatedLinks.endless());
        links.runFor(10 * SECOND);
        long before = pinned.delivered;
        long raisedAt = links.now;
        pinned.flow.setConditions(fast, delayMs);
        // The grant on the air carries at the new rate from the change (what fits of it before its end),
        // the other link has its turn (one quantum), then the raised link's next grant carries the
        // rest at 54 Mbit/s: everything held arrives within two quanta and the delay.
        long waiting = pinned.flow.held();
        links.runUntil(raisedAt + 2 * Airtime.QUANTUM_NS + delayMs * MS);
        assertTrue(pinned.delivered - before >= waiting, "the " + waiting + " bytes that waited at 1 bit/s arrive within "
                + "two quanta and the delay: " + (pinned.delivered - before) + " bytes");
        long nearBefore = near.delivered;
        long pinnedBefore = pinned.delivered;
        links.runFor(10 * SECOND);
        assertEquals(0.5, (pinned.delivered - pinnedBefore) * 8.0 / fast / 10, 0.05, "then half the airtime each");
        assertEquals(0.5, (near.delivered - nearBefore) * 8.0 / fast / 10, 0.05);
    }

    /**
     * Issue 27's probe on the moved clock: A-B at 1 bit/s beside A-C at 54 Mbit/s, A-B raised to
     * 54 Mbit/s at 40 moments over two turns of A's radio (during A-B's own grant and during
     * A-C's). The grant on the air carries at the new rate from the change, and a grant booked
     * ahead is due once the bytes it carries are on the air: B's next byte comes within one quantum
     * (A-C's turn at most), the airtime of what A-B held (a frame, 1,500 bytes: 0.22 ms) and the
     * delay. The bytes read after the raise ride in the time A-B's grants booked at 1 bit/s have
     * to spare: within four quanta and the delay B has had a whole quantum at 54 Mbit/s more.
     */
    @Test
    void aRateRaisedReachesTheLinkWithinOneQuantumAndItsDelayWhateverTheMoment() {
        long fast = 54_000_000;
        for (int delayMs : new int[] {0, 2}) {
            long worst = 0;
            for (int moment = 0; moment < 40; moment++) {
                SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, false);
                Lane pinned = links.add("A", "B", 1, delayMs, CHUNK, SimulatedLinks.endless());
                links.add("A", "C", fast, delayMs, CHUNK, SimulatedLinks.endless());
                links.runFor(SECOND + moment * 100_000L);
                long held = pinned.flow.held();
                long raisedAt = links.now;
                pinned.flow.setConditions(fast, delayMs);
                long before = pinned.delivered;
                long next = links.runUntilDelivered(pinned, before + 1, raisedAt + SECOND) - raisedAt;
                long bound = Airtime.QUANTUM_NS + Bitrate.nanos(held, fast) + delayMs * MS;
                assertTrue(next >= delayMs * MS && next <= bound, "raised " + moment * 100 + " µs into the turns, delay " + delayMs
                        + " ms: B's next byte " + next + " ns after, bound " + bound);
                worst = Math.max(worst, next);
                links.runUntil(raisedAt + 4 * Airtime.QUANTUM_NS + delayMs * MS);
                long quantum = Bitrate.bytesIn(Airtime.QUANTUM_NS, fast);
                assertTrue(pinned.delivered - before >= held + quantum, "raised " + moment * 100 + " µs into the turns: "
                        + (pinned.delivered - before) + " bytes within four quanta, not " + held + " held and a quantum's " + quantum);
            }
            // The bound is reached: a raise at the start of A-C's turn waits for all of it.
            assertTrue(worst > Airtime.QUANTUM_NS + delayMs * MS, "the worst moment, " + worst + " ns, waits A-C's turn");
        }
    }

    @Test
    void aRelayThatReceivesAndSendsAgainHalvesTheGoodput() {
        long rate = 11_000_000;
        SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, true);
        Lane in = links.add("A", "R", rate, 2, CHUNK, SimulatedLinks.endless());
        Lane out = links.add("R", "B", rate, 2, CHUNK, links.relayOf(in));
        links.runFor(10 * SECOND);
        double half = rate * 10 / 8.0 / 2;
        assertTrue(out.delivered <= half * 1.01, "A to B through R: " + out.delivered + " bytes, more than half the rate");
        assertTrue(out.delivered >= half * 0.9, "A to B through R: " + out.delivered + " bytes, well under half the rate");
        assertEquals(1, links.airtime.inUse("R", links.now), 0.03, "the relay's radio is always busy");
    }

    @Test
    void withoutSharedAirtimeEachDirectionHasItsOwnRate() {
        long rate = 6_000_000;
        SimulatedLinks links = new SimulatedLinks(Airtime.unshared(), 0, false);
        Lane toB = links.add("A", "B", rate, 2, CHUNK, SimulatedLinks.endless());
        Lane toC = links.add("A", "C", rate, 2, CHUNK, SimulatedLinks.endless());
        Lane back = links.add("B", "A", rate, 2, CHUNK, SimulatedLinks.endless());
        links.runFor(2 * SECOND);
        double expected = rate * 2 / 8.0;
        for (Lane lane : new Lane[] {toB, toC, back}) {
            assertEquals(expected, lane.delivered, expected / 100);
        }
    }

    @Test
    void aRateChangeReachesTheBytesStillWaiting() {
        SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, true);
        assertEquals(12_500, ShapedFlow.capacity(1_000_000, 0, 100), "1 Mbit/s x 100 ms / 8");
        assertEquals(2_500, ShapedFlow.capacity(1_000_000, 0, ShapingConfig.DEFAULT_QUEUE_MS), "1 Mbit/s x 20 ms / 8");
        long capacity = 5096;
        Lane lane = links.add("A", "B", 1_000_000, 0, 100, CHUNK, SimulatedLinks.finite(capacity), null);
        links.runFor(MS);
        assertEquals(capacity, lane.read, "all read at once");
        lane.flow.setConditions(8_000_000, 0);
        // Four grants of 2 ms were taken at 1 Mbit/s (0-2 ms on the air, 2-8 ms booked ahead). The
        // one on the air carries at 8 Mbit/s from the change at 1 ms (125 + 1,000 bytes); those not
        // begun carry 2,000 bytes each: the last 1,971 bytes are on the air 1.971 ms into the third
        // grant, and due then, not at its end. At 1 Mbit/s they would take 38.8 ms.
        links.runUntil(2 * MS);
        assertEquals(125 + 1000, lane.delivered);
        links.runUntil(4 * MS);
        assertEquals(125 + 1000 + 2000, lane.delivered);
        links.runUntil(4 * MS + 1_971_000 - 1);
        assertEquals(125 + 1000 + 2000, lane.delivered);
        links.runUntil(4 * MS + 1_971_000);
        assertEquals(capacity, lane.delivered);
        assertEquals(lane.sent.getValue(), lane.got.getValue());
    }

    @Test
    void aDirectionHoldsItsDelayAndItsQueueAtItsRateAndNoMore() {
        for (long rate : new long[] {1_000_000, 6_000_000, 24_000_000}) {
            SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, false);
            Lane lane = links.add("A", "B", rate, 2, CHUNK, SimulatedLinks.endless());
            links.runFor(2 * SECOND);
            long most = Bitrate.bytesIn((2 + ShapingConfig.DEFAULT_QUEUE_MS) * MS, rate);
            assertEquals(most, lane.mostHeld, Bitrate.format(rate) + ": the delay and the default queue at the rate");
            assertEquals(rate * 2 / 8.0, lane.delivered, rate * 2 / 8.0 / 100, Bitrate.format(rate) + ": and the rate is kept");
        }
        assertEquals(ShapedFlow.MIN_HELD, ShapedFlow.capacity(1, 2, ShapingConfig.DEFAULT_QUEUE_MS), "a frame at least");
        assertThrows(IllegalArgumentException.class, () -> new ShapedFlow(Airtime.shared().open("A", "B", 0), 1, 2, 9));
    }

    @Test
    void aThreadThatWakesLateLosesNoRateItsGrantsAreBookedAhead() throws Exception {
        long rate = 24_000_000;
        ShapedFlow flow = new ShapedFlow(Airtime.shared().open("A", "B", 0), rate, 2, ShapingConfig.DEFAULT_QUEUE_MS);
        Sink target = new Sink();
        long now = 0;
        long late = 3 * MS; // a busy machine: every wake-up 3 ms after it was due
        while (now < 2 * SECOND) {
            flow.accept(ByteBuffer.wrap(new byte[flow.room()]), now);
            flow.writeTo(target, now);
            long wait = flow.nanosUntilNext(now);
            now += (wait == Long.MAX_VALUE ? 0 : wait) + late;
        }
        double expected = rate * 2 / 8.0;
        assertTrue(target.bytes >= expected * 0.99, target.bytes + " bytes of " + expected + " in 2 s");
    }

    /** A target that takes everything. */
    private static final class Sink implements OpenTarget {
        long bytes;

        @Override
        public int write(ByteBuffer buffer) {
            int count = buffer.remaining();
            buffer.position(buffer.limit());
            bytes += count;
            return count;
        }
    }

    @Test
    void aDirectionNeverHoldsMoreThanItsCapacity() {
        SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, false);
        Lane lane = links.add("A", "B", 6_000_000, 100, CHUNK, SimulatedLinks.endless(), new Random(16));
        int queueMs = ShapingConfig.DEFAULT_QUEUE_MS;
        assertEquals(6_000_000 * (100 + queueMs) / 1000 / 8, lane.flow.capacity(), "rate x (delay + queue) / 8");
        links.runFor(2 * SECOND);
        assertTrue(lane.mostHeld <= lane.flow.capacity(), lane.mostHeld + " held");
        assertTrue(lane.mostHeld >= 6_000_000 * 100 / 1000 / 8, "the capacity is what limits the reading: " + lane.mostHeld);

        lane.flow.setConditions(1_000_000, 100);
        assertEquals(1_000_000 * (100 + queueMs) / 1000 / 8, lane.flow.capacity());
        assertEquals(0, lane.flow.room(), "a slower rate: no room until what is held drains");
        assertThrows(IllegalStateException.class, () -> lane.flow.accept(ByteBuffer.allocate(1), links.now));
        lane.mostHeld = 0;
        links.runFor(2 * SECOND);
        assertTrue(lane.flow.held() <= lane.flow.capacity());
    }

    @Test
    void aTargetThatTakesNothingStopsTheReadingAndLosesNothing() {
        SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, true);
        Lane lane = links.add("A", "B", 11_000_000, 2, CHUNK, SimulatedLinks.endless());
        lane.takes = () -> 0;
        links.runFor(SECOND);
        assertEquals(0, lane.delivered);
        assertEquals(lane.flow.capacity(), lane.read, "read up to the capacity, then no more");
        assertEquals(lane.flow.capacity(), lane.flow.due(links.now), "all of it due, waiting for the target");
        lane.takes = null;
        links.runFor(SECOND);
        assertTrue(lane.delivered > lane.flow.capacity());
    }

    @Test
    void inAFullMeshOfBusyDirectionsEveryRadioIsKeptBusy() {
        int robots = 10;
        SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, false);
        for (int i = 0; i < robots; i++) {
            for (int j = 0; j < robots; j++) {
                if (i != j) {
                    links.add("R" + i, "R" + j, 6_000_000 + 1_000_000L * ((i + j) % 7), 2, CHUNK, SimulatedLinks.endless());
                }
            }
        }
        links.runFor(SECOND);
        for (int i = 0; i < robots; i++) {
            // First come, first served (each grant after both radios' last reservation) kept them 27 % busy.
            assertTrue(links.airtime.inUse("R" + i, links.now) >= 0.99, "R" + i + ": " + links.airtime.inUse("R" + i, links.now));
        }
    }

    @Test
    void aDirectionWhoseTargetHasNotTakenAllTakesOnlyAirtimeNobodyAskedFor() {
        long rate = 12_000_000;
        SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, false);
        Lane full = links.add("A", "B", rate, 2, CHUNK, SimulatedLinks.endless());
        full.takes = () -> 0;
        Lane busy = links.add("A", "C", rate, 2, CHUNK, SimulatedLinks.finite(rate / 8 / 5)); // 200 ms at the whole rate
        long finished = links.runUntilDelivered(busy, rate / 8 / 5, SECOND);
        // Taking turns to the end, A to B had the air for all it held (33,000 bytes) and A to C was done at 224 ms.
        assertTrue(finished > 0 && finished <= 215 * MS, "A to C had A's radio but for the grants A to B booked before: done at " + finished);
        long dueWhileBusy = full.flow.due(finished);
        assertTrue(dueWhileBusy < full.flow.capacity() / 2,
                "A to B stopped taking turns once B's program had not taken its bytes: " + dueWhileBusy + " bytes had the air");
        links.runFor(100 * MS);
        assertEquals(full.flow.capacity(), full.flow.due(links.now), "A idle: A to B had the airtime nobody asked for");
        full.takes = null;
        links.runFor(100 * MS);
        assertTrue(full.delivered >= rate / 8 / 10, "its program reads again: it takes turns again, " + full.delivered);
    }

    @Test
    void nothingIsLostReorderedOrDuplicated() throws IOException {
        Random random = new Random(1616);
        SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 123_456_789, true);
        long total = 1_500_000;
        Lane ab = links.add("A", "B", 6_000_000, 2, 3000, SimulatedLinks.finite(total), new Random(1));
        Lane ba = links.add("B", "A", 1_000_000, 20, 1500, SimulatedLinks.finite(total), new Random(2));
        Lane ac = links.add("A", "C", 54_000_000, 0, 9000, SimulatedLinks.finite(total), new Random(3));
        Lane cb = links.add("C", "B", 512_000, 300, 700, SimulatedLinks.finite(total / 8), new Random(4));
        long[] rates = {512_000, 1_000_000, 6_000_000, 11_000_000, 24_000_000, 54_000_000};
        int[] delays = {0, 2, 50, 300};
        for (Lane lane : links.lanes) {
            lane.takes = () -> random.nextInt(4) == 0 ? random.nextInt(2000) : Long.MAX_VALUE;
        }
        for (int round = 0; round < 200; round++) {
            links.runFor((1 + random.nextInt(40)) * MS);
            Lane lane = links.lanes.get(random.nextInt(links.lanes.size()));
            lane.flow.setConditions(rates[random.nextInt(rates.length)], delays[random.nextInt(delays.length)]);
        }
        for (Lane lane : links.lanes) {
            lane.flow.setConditions(54_000_000, 2);
        }
        links.runFor(10 * SECOND);
        for (Lane lane : new Lane[] {ab, ba, ac}) {
            assertEquals(total, lane.delivered);
            assertEquals(lane.sent.getValue(), lane.got.getValue(), "the checksums");
            assertEquals(0, lane.flow.held());
        }
        assertEquals(total / 8, cb.delivered);
        assertEquals(cb.sent.getValue(), cb.got.getValue());
        assertEquals(0, ab.flow.writeTo(new Refusing(), links.now), "nothing left to write");
    }

    /** A target that must not be written to. */
    private static final class Refusing implements OpenTarget {
        @Override
        public int write(ByteBuffer bytes) {
            throw new AssertionError("written to");
        }
    }
}
