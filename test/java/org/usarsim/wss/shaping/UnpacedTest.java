package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** A link not shaped: every byte read may go at once, written from the buffer it was read into. */
class UnpacedTest {

    @Test
    void aChunkIsDueAtOnceAndWrittenFromTheBufferItWasReadInto() throws Exception {
        Unpaced pacing = new Unpaced();
        assertEquals(Integer.MAX_VALUE, pacing.room(), "as much as the buffer takes");
        ByteBuffer buffer = ByteBuffer.allocateDirect(64);
        buffer.put(new byte[40]).flip();
        pacing.accept(buffer, 0);
        assertEquals(40, pacing.due(0));
        assertEquals(40, pacing.held());
        assertEquals(Long.MAX_VALUE, pacing.nanosUntilNext(0), "nothing waits for time");
        assertFalse(pacing.timed(), "so the loop reads no clock");
        Target target = new Target(Integer.MAX_VALUE);
        assertEquals(40, pacing.writeTo(target, 0));
        assertSame(buffer, target.buffers.get(0), "no copy");
        assertEquals(0, pacing.held());
        assertEquals(Integer.MAX_VALUE, pacing.room());
    }

    @Test
    void whatATargetDidNotTakeWaitsAndNothingIsReadMeanwhile() throws Exception {
        Unpaced pacing = new Unpaced();
        ByteBuffer buffer = ByteBuffer.allocate(100);
        buffer.put(new byte[100]).flip();
        pacing.accept(buffer, 0);
        assertEquals(30, pacing.writeTo(new Target(30), 0));
        assertEquals(70, pacing.due(0), "the rest is due");
        assertEquals(0, pacing.room(), "read again only once the chunk is out: the sender feels the full target");
        assertThrows(IllegalStateException.class, () -> pacing.accept(ByteBuffer.allocate(1), 0));
        assertEquals(0, pacing.writeTo(new Target(0), 0));
        assertEquals(70, pacing.writeTo(new Target(Integer.MAX_VALUE), 0));
        assertEquals(0, pacing.held());
        assertEquals(0, pacing.writeTo(new Target(Integer.MAX_VALUE), 0), "nothing left");
    }

    /** A target that takes at most {@code most} bytes a write, and remembers the buffers it was given. */
    private static final class Target implements OpenTarget {
        private final int most;
        final List<ByteBuffer> buffers = new ArrayList<>();

        Target(int most) {
            this.most = most;
        }

        @Override
        public int write(ByteBuffer bytes) {
            buffers.add(bytes);
            int count = Math.min(most, bytes.remaining());
            bytes.position(bytes.position() + count);
            return count;
        }
    }
}
