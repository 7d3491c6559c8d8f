package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.channels.Channels;
import java.nio.channels.WritableByteChannel;
import org.junit.jupiter.api.Test;

/**
 * A shaped direction's stages (docs/shaping.md, "Stages"): the queue, the air and what follows
 * the air, on a clock the test moves. A stage after the delay, as a jitter would be one, holds
 * the bytes longer and never reorders them.
 */
class StagesTest {

    private static final long MS = 1_000_000;
    private static final long RATE = 1_000_000;
    /** 64 bytes at 1 Mbit/s. */
    private static final long AIRTIME_64 = 512_000;

    @Test
    void aStageAfterTheDelayHoldsTheBytesLongerAndTheCapacityMakesRoomForIt() throws Exception {
        AfterAir threeMore = stage(3 * MS);
        ShapedFlow flow = new ShapedFlow(Airtime.unshared().open("A", "B", 0), RATE, 5, ShapingConfig.DEFAULT_QUEUE_MS, threeMore);
        assertEquals(Bitrate.bytesIn((5 + 3 + ShapingConfig.DEFAULT_QUEUE_MS) * MS, RATE), flow.capacity(),
                "the rate x (the delay, the stage's 3 ms and the queue)");
        flow.accept(ByteBuffer.wrap(new byte[64]), 0);
        long due = AIRTIME_64 + 5 * MS + 3 * MS;
        assertEquals(due, flow.nanosUntilNext(0));
        assertEquals(0, flow.due(due - 1));
        assertEquals(64, flow.due(due));
        flow.setConditions(RATE, 20);
        assertEquals(Bitrate.bytesIn((20 + 3 + ShapingConfig.DEFAULT_QUEUE_MS) * MS, RATE), flow.capacity(), "a new delay, the stage's kept");
    }

    @Test
    void bytesAStageLetsGoSoonerWaitForThoseBeforeThem() throws Exception {
        // The first grant is held 10 ms more, the later ones not: a jitter that drew a long wait first.
        AfterAir firstLate = new AfterAir() {
            private boolean first = true;

            @Override
            public long dueAt(long offAirNs) {
                long due = first ? offAirNs + 10 * MS : offAirNs;
                first = false;
                return due;
            }

            @Override
            public long holdsNs() {
                return 10 * MS;
            }
        };
        ShapedFlow flow = new ShapedFlow(Airtime.unshared().open("A", "B", 0), RATE, 0, ShapingConfig.DEFAULT_QUEUE_MS, firstLate);
        flow.accept(ByteBuffer.wrap(bytes(0, 64)), 0);
        flow.accept(ByteBuffer.wrap(bytes(64, 64)), MS); // after the first grant's end: a grant of its own
        long secondOffAir = MS + AIRTIME_64;
        assertEquals(0, flow.due(secondOffAir), "the second grant's bytes wait for the first's");
        long firstDue = AIRTIME_64 + 10 * MS;
        assertEquals(0, flow.due(firstDue - 1));
        assertEquals(128, flow.due(firstDue), "then both go, in order");
        ByteArrayOutputStream target = new ByteArrayOutputStream();
        WritableByteChannel out = Channels.newChannel(target);
        assertEquals(128, flow.writeTo(out, firstDue));
        byte[] written = target.toByteArray();
        for (int i = 0; i < 128; i++) {
            assertEquals((byte) i, written[i], "byte " + i);
        }
    }

    @Test
    void stagesChainInOrder() {
        AfterAir onWholeMilliseconds = new AfterAir() {
            @Override
            public long dueAt(long offAirNs) {
                return (offAirNs + MS - 1) / MS * MS;
            }

            @Override
            public long holdsNs() {
                return MS;
            }
        };
        assertEquals(MS, stage(MS / 2).then(onWholeMilliseconds).dueAt(100), "half a millisecond more, then the next whole one");
        assertEquals(MS + MS / 2, onWholeMilliseconds.then(stage(MS / 2)).dueAt(100), "the next whole millisecond, then half more");
        assertEquals(MS + MS / 2, stage(MS / 2).then(onWholeMilliseconds).holdsNs());
    }

    @Test
    void theDelayAddsItsTime() {
        Delay delay = new Delay(7);
        assertEquals(100 + 7 * MS, delay.dueAt(100));
        delay.set(0);
        assertEquals(100, delay.dueAt(100));
    }

    /** A stage holding every grant {@code nanos} more. */
    private static AfterAir stage(long nanos) {
        return new AfterAir() {
            @Override
            public long dueAt(long offAirNs) {
                return offAirNs + nanos;
            }

            @Override
            public long holdsNs() {
                return nanos;
            }
        };
    }

    private static byte[] bytes(int from, int count) {
        byte[] bytes = new byte[count];
        for (int i = 0; i < count; i++) {
            bytes[i] = (byte) (from + i);
        }
        return bytes;
    }
}
