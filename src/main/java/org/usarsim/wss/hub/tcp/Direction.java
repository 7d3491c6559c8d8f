package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.SocketChannel;
import java.util.concurrent.atomic.LongAdder;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.PairStats;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.ShapedFlow;

/**
 * One way of a link: reads from one channel into its buffer, and counts what the forwarding loop
 * ({@link UnshapedForwarding} or {@link ShapedForwarding}) wrote to the other. When to read and
 * when to write is the loop's; reading, dropping and counting are here, once for both.
 */
final class Direction {

    private static final Logger LOG = Logger.getLogger(Link.class.getName());
    /** How many chunks one direction moves before the other gets a turn. */
    static final int CHUNKS_PER_TURN = 16;

    private final Link link;
    final SocketChannel in;
    final SocketChannel out;
    final String fromRobot;
    final String toRobot;
    final ByteBuffer buffer;
    /** The pair's count of bytes written this way: one add per write, no lock. */
    private final LongAdder forwarded;
    private final WssEventListener events;
    /** The input ended (end of stream, a reset or a failure). */
    private boolean ended;

    Direction(Link link, SocketChannel in, SocketChannel out, String fromRobot, String toRobot, int chunkSize, PairStats stats,
            WssEventListener events) {
        this.link = link;
        this.in = in;
        this.out = out;
        this.fromRobot = fromRobot;
        this.toRobot = toRobot;
        this.buffer = ByteBuffer.allocateDirect(chunkSize);
        this.forwarded = stats.bytesFrom(fromRobot);
        this.events = events;
    }

    /**
     * Writes what waits in {@code buffer} to the output and counts it, unless the link is closed:
     * under the link's send lock, so that once {@link Link#close} returns no byte more reaches the
     * target nor is reported (a pair forced down: its DATA_SENT lines end before FORCED, issue 27).
     */
    void send(ByteBuffer buffer) throws IOException {
        synchronized (link.sending) {
            if (!link.isClosed()) {
                sent(out.write(buffer));
            }
        }
    }

    /** As {@link #send(ByteBuffer)}, for what a shaped flow has due at {@code now}. */
    void send(ShapedFlow flow, long now) throws IOException {
        synchronized (link.sending) {
            if (!link.isClosed()) {
                sent(flow.writeTo(out, now));
            }
        }
    }

    /**
     * The one count of bytes sent: what reached the target's socket, for the statistics and the
     * event log alike.
     */
    private void sent(int written) {
        if (written > 0) {
            forwarded.add(written);
            events.dataSent(fromRobot, toRobot, written);
        }
    }

    /** Whether the input ended (end of stream, a reset or a failure). */
    boolean ended() {
        return ended;
    }

    /**
     * Reads into the buffer: -1 at end of stream, and also when the side reset the connection
     * or failed, since it is gone either way and what was read from it is still delivered; the
     * direction has then {@link #ended}.
     */
    int read() {
        int read;
        try {
            read = in.read(buffer);
        } catch (IOException e) {
            if (!link.isClosed()) {
                LOG.fine(() -> link + ": " + fromRobot + "'s side failed: " + e);
            }
            read = -1;
        }
        if (read < 0) {
            ended = true;
        }
        return read;
    }

    /** Reads and drops what is there, once the other side has gone; @return true at end of stream. */
    boolean drop() {
        int read = 0;
        for (int i = 0; i < CHUNKS_PER_TURN; i++) {
            buffer.clear();
            read = read();
            if (read <= 0) {
                break;
            }
        }
        return read < 0;
    }
}
