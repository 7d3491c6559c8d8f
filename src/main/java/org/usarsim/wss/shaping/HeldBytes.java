package org.usarsim.wss.shaping;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.WritableByteChannel;
import java.util.ArrayDeque;

/**
 * The queue of a shaped direction: the bytes read and not yet written, in order, as copies (the
 * link reads into its buffer again at once), each buffer's position what was written of it. The
 * stream's offsets: {@link #received} bytes read, {@link #written} written. When they may be
 * written is the other stages' to say ({@link ShapedFlow}).
 */
final class HeldBytes {

    private final ArrayDeque<ByteBuffer> chunks = new ArrayDeque<>();
    private long received;
    private long written;

    /** The bytes read so far: the offset of the next byte read. */
    long received() {
        return received;
    }

    /** The bytes written so far. */
    long written() {
        return written;
    }

    /** The bytes read and not yet written. */
    long held() {
        return received - written;
    }

    /** Copies {@code bytes}' remaining ones; the buffer's position moves to its limit. */
    void add(ByteBuffer bytes) {
        int count = bytes.remaining();
        if (count > 0) {
            byte[] copy = new byte[count];
            bytes.get(copy);
            chunks.addLast(ByteBuffer.wrap(copy));
            received += count;
        }
    }

    /**
     * Writes the bytes before offset {@code upTo} not yet written to {@code out}, in order, until
     * all of them are written or {@code out} takes no more.
     *
     * @return the bytes written
     */
    int writeTo(WritableByteChannel out, long upTo) throws IOException {
        int total = 0;
        while (written < upTo) {
            ByteBuffer head = chunks.peekFirst();
            head.limit((int) Math.min(head.capacity(), head.position() + (upTo - written)));
            int count = out.write(head);
            written += count;
            total += count;
            if (head.hasRemaining()) {
                break;
            }
            if (head.position() == head.capacity()) {
                chunks.pollFirst();
            }
        }
        return total;
    }
}
