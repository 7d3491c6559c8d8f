package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.SocketChannel;
import java.util.concurrent.atomic.LongAdder;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.PairStats;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.Pacing;

/**
 * One way of a link: reads from one channel into its buffer, hands what it read to its
 * {@link Pacing}, and writes to the other channel what the pacing has due, counting it. When the
 * loop ({@link Forwarding}) turns to it is the loop's; how much may be read and when it may be
 * written is the pacing's; reading, writing, dropping and counting are here, once for a shaped
 * and an unshaped link alike.
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
    /** When the bytes read may be written: at once ({@link org.usarsim.wss.shaping.Unpaced}), or shaped. */
    final Pacing pacing;
    /** The pair's count of bytes written this way: one add per write, no lock. */
    private final LongAdder forwarded;
    private final WssEventListener events;
    /** The input ended (end of stream, a reset or a failure). */
    private boolean ended;
    /** Nagle's algorithm is on for the output (see {@link #coalesce}). */
    private boolean coalescing;
    /** The output took less than was due: it is written again once it says it takes more. */
    private boolean outputFull;
    /** The output said it takes more (OP_WRITE) since the last write. */
    private boolean outputReady;

    Direction(Link link, SocketChannel in, SocketChannel out, String fromRobot, String toRobot, int chunkSize, PairStats stats,
            WssEventListener events, Pacing pacing) {
        this.link = link;
        this.in = in;
        this.out = out;
        this.fromRobot = fromRobot;
        this.toRobot = toRobot;
        this.buffer = ByteBuffer.allocateDirect(chunkSize);
        this.pacing = pacing;
        this.forwarded = stats.bytesFrom(fromRobot);
        this.events = events;
    }

    /**
     * Reads and hands over chunks while each read fills what the pacing had room for (more is
     * probably right behind it), writing at once what is due, until the pacing has no room or the
     * turn is over. A shorter read means the input is drained for now, so the link goes back to
     * waiting without asking again.
     */
    void move(long now) throws IOException {
        for (int i = 0; i < CHUNKS_PER_TURN; i++) {
            int room = pacing.room();
            if (room == 0) {
                return;
            }
            buffer.clear();
            buffer.limit(Math.min(room, buffer.capacity()));
            int asked = buffer.limit();
            int read = read();
            if (read <= 0) {
                return; // drained for now, or ended
            }
            boolean full = read == asked;
            buffer.flip();
            pacing.accept(buffer, now);
            long due = pacing.due(now);
            coalesce(full && due == pacing.held());
            if (due > 0 && !outputFull) {
                send(now);
            }
            if (!full) {
                return;
            }
        }
    }

    /** Writes what is due, unless the output was full and has not said since that it takes more. */
    void writeDue(long now) throws IOException {
        if (outputFull && !outputReady) {
            return;
        }
        outputReady = false;
        if (pacing.due(now) > 0) {
            send(now);
        }
    }

    /** The output said it takes more (OP_WRITE), or not, at the last wait. */
    void outputReady(boolean ready) {
        outputReady = ready;
    }

    /**
     * While a burst of full chunks passes straight through (every byte held due at once: a link not
     * shaped), lets the OS hold the last partial segment of one chunk until the next chunk fills it
     * (Nagle's algorithm), instead of sending a tiny segment per chunk. Off again for any shorter
     * read and before the link waits: turning TCP_NODELAY back on sends what is held at once, so no
     * message waits for an ACK.
     */
    void coalesce(boolean on) throws IOException {
        if (on != coalescing) {
            out.setOption(StandardSocketOptions.TCP_NODELAY, !on);
            coalescing = on;
        }
    }

    /**
     * Writes what the pacing has due at {@code now} to the output and counts it, unless the link
     * is closed: under the link's send lock, so that once {@link Link#close} returns no byte more
     * reaches the target nor is reported (a pair forced down: its DATA_SENT lines end before
     * FORCED, issue 27).
     */
    private void send(long now) throws IOException {
        synchronized (link.sending) {
            if (!link.isClosed()) {
                sent(pacing.writeTo(out, now));
            }
        }
        outputFull = pacing.due(now) > 0;
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
    private int read() {
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
