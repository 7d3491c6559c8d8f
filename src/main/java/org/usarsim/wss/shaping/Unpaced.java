package org.usarsim.wss.shaping;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.WritableByteChannel;

/**
 * A direction that is not shaped (wss.shaping = off): every byte read may be written at once. It
 * keeps the buffer it was given, never a copy, and has no room until all of it is written, so a
 * chunk read is written completely before the direction reads again, and a target that takes
 * nothing stops the reading (TCP's back-pressure reaches the sender). No clock, no cost per byte.
 */
public final class Unpaced implements Pacing {

    /** The buffer taken, its bytes not yet written between its position and its limit; null when all are. */
    private ByteBuffer waiting;

    @Override
    public int room() {
        return waiting == null ? Integer.MAX_VALUE : 0;
    }

    @Override
    public void accept(ByteBuffer bytes, long nowNs) {
        if (waiting != null) {
            throw new IllegalStateException(bytes.remaining() + " bytes read while " + waiting.remaining() + " wait");
        }
        if (bytes.hasRemaining()) {
            waiting = bytes;
        }
    }

    @Override
    public long due(long nowNs) {
        return held();
    }

    @Override
    public int writeTo(WritableByteChannel out, long nowNs) throws IOException {
        if (waiting == null) {
            return 0;
        }
        int written = out.write(waiting);
        if (!waiting.hasRemaining()) {
            waiting = null;
        }
        return written;
    }

    @Override
    public long nanosUntilNext(long nowNs) {
        return Long.MAX_VALUE;
    }

    @Override
    public long held() {
        return waiting == null ? 0 : waiting.remaining();
    }

    @Override
    public boolean timed() {
        return false;
    }

    @Override
    public void close() {
        waiting = null;
    }
}
