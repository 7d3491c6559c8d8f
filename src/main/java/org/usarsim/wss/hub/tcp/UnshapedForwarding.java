package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.StandardSocketOptions;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;

/**
 * The loop of a link forwarding as fast as the machine goes (wss.shaping = off): waits on the
 * selector over both channels and copies chunks each way, unchanged and in order; a side's end
 * stops the reading, and both streams end once what was read is written.
 */
final class UnshapedForwarding extends Forwarding {

    private final Way upWay;
    private final Way downWay;

    UnshapedForwarding(Link link, Selector selector, Direction up, Direction down) throws IOException {
        super(link, selector, up, down);
        this.upWay = new Way(up);
        this.downWay = new Way(down);
    }

    @Override
    void forward() throws IOException {
        while (!link.isClosed()) {
            upWay.coalesce(false);
            downWay.coalesce(false);
            selector.select();
            boolean sourceReady = sourceKey.isValid() && selector.selectedKeys().contains(sourceKey);
            boolean targetReady = targetKey.isValid() && selector.selectedKeys().contains(targetKey);
            int sourceOps = sourceReady ? sourceKey.readyOps() : 0;
            int targetOps = targetReady ? targetKey.readyOps() : 0;
            selector.selectedKeys().clear();
            if (link.isClosed()) {
                return;
            }
            if ((targetOps & SelectionKey.OP_WRITE) != 0) {
                upWay.flush();
            }
            if ((sourceOps & SelectionKey.OP_WRITE) != 0) {
                downWay.flush();
            }
            boolean ended = up.ended() || down.ended();
            if (!ended && (sourceOps & SelectionKey.OP_READ) != 0) {
                upWay.move();
            }
            if (!ended && (targetOps & SelectionKey.OP_READ) != 0) {
                downWay.move();
            }
            ended = up.ended() || down.ended();
            if (ended && !upWay.pending && !downWay.pending) {
                upWay.coalesce(false);
                downWay.coalesce(false);
                finish();
                return;
            }
            sourceKey.interestOps(interest(ended, upWay, downWay));
            targetKey.interestOps(interest(ended, downWay, upWay));
        }
    }

    /** A channel is read while nothing it sent waits to be written, and written while something waits for it. */
    private static int interest(boolean ended, Way from, Way to) {
        int ops = !ended && !from.pending ? SelectionKey.OP_READ : 0;
        return to.pending ? ops | SelectionKey.OP_WRITE : ops;
    }

    /** What one direction holds between turns: a chunk read and not yet all written. */
    private static final class Way {
        private final Direction direction;
        /** The buffer holds read bytes not yet written. */
        private boolean pending;
        /** Nagle's algorithm is on for the output (see {@link #coalesce}). */
        private boolean coalescing;

        Way(Direction direction) {
            this.direction = direction;
        }

        /**
         * Reads and writes chunks while each read fills a whole chunk (more is probably right
         * behind it), until the output is full or the turn is over. A shorter read means the
         * input is drained for now, so the link goes back to waiting without asking again.
         */
        void move() throws IOException {
            for (int i = 0; i < Direction.CHUNKS_PER_TURN && !pending; i++) {
                int read = direction.read();
                if (read <= 0) {
                    return; // drained for now, or ended
                }
                boolean full = read == direction.buffer.capacity();
                coalesce(full);
                direction.buffer.flip();
                pending = true;
                flush();
                if (!full) {
                    return;
                }
            }
        }

        /**
         * While a burst of full chunks passes, lets the OS hold the last partial segment of one
         * chunk until the next chunk fills it (Nagle's algorithm), instead of sending a tiny
         * segment per chunk. Off again for any shorter read and before the link waits: turning
         * TCP_NODELAY back on sends what is held at once, so no message waits for an ACK.
         */
        void coalesce(boolean on) throws IOException {
            if (on != coalescing) {
                direction.out.setOption(StandardSocketOptions.TCP_NODELAY, !on);
                coalescing = on;
            }
        }

        /** Writes what waits; the buffer is cleared once all of it is out. */
        void flush() throws IOException {
            if (!pending) {
                return;
            }
            direction.send(direction.buffer);
            if (!direction.buffer.hasRemaining()) {
                direction.buffer.clear();
                pending = false;
            }
        }
    }
}
