package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.HubClock;

/**
 * A link's one forwarding loop, on the link's own thread, shaped or not: its selector over both
 * sockets and its two directions, each asking its {@link org.usarsim.wss.shaping.Pacing} how much
 * it may read and what it may write (docs/shaping.md, "Stages"). At each turn it writes what is
 * due each way, waits on the selector at most until a direction has something new to do (for an
 * unshaped link, until a socket is ready), then reads each way what the pacing has room for. A
 * side's end stops the reading, and both streams end once what was read is written
 * ({@link #finish}).
 */
final class Forwarding {

    private static final Logger LOG = Logger.getLogger(Link.class.getName());
    /** How long a finished link waits for both sides to end their streams. */
    private static final long FINISH_NS = TimeUnit.SECONDS.toNanos(5);

    private final Link link;
    private final Selector selector;
    private final HubClock clock;
    /** From the source robot to the target robot, and back. */
    private final Direction up;
    private final Direction down;
    private final SelectionKey sourceKey;
    private final SelectionKey targetKey;
    /** Whether a direction's pacing needs the time; if neither does (unshaped), the loop reads no clock. */
    private final boolean timed;

    Forwarding(Link link, Selector selector, HubClock clock, Direction up, Direction down) throws IOException {
        this.link = link;
        this.selector = selector;
        this.clock = clock;
        this.up = up;
        this.down = down;
        this.sourceKey = up.in.register(selector, SelectionKey.OP_READ);
        this.targetKey = down.in.register(selector, SelectionKey.OP_READ);
        this.timed = up.pacing.timed() || down.pacing.timed();
    }

    /** Forwards until the link is closed or both streams have ended. */
    void forward() throws IOException {
        while (!link.isClosed()) {
            long now = now();
            up.writeDue(now);
            down.writeDue(now);
            up.coalesce(false); // what Nagle's algorithm holds goes before the link waits or ends
            down.coalesce(false);
            boolean ended = up.ended() || down.ended();
            if (ended && up.pacing.held() == 0 && down.pacing.held() == 0) {
                finish();
                return;
            }
            sourceKey.interestOps(interest(ended, up, down, now));
            targetKey.interestOps(interest(ended, down, up, now));
            waitAtMost(Math.min(up.pacing.nanosUntilNext(now), down.pacing.nanosUntilNext(now)));
            int sourceOps = readyOps(sourceKey);
            int targetOps = readyOps(targetKey);
            selector.selectedKeys().clear();
            if (link.isClosed()) {
                return;
            }
            up.outputReady((targetOps & SelectionKey.OP_WRITE) != 0);
            down.outputReady((sourceOps & SelectionKey.OP_WRITE) != 0);
            long woke = now(); // one clock read for both directions' reads
            if ((sourceOps & SelectionKey.OP_READ) != 0 && !up.ended() && !down.ended()) {
                up.move(woke);
            }
            if ((targetOps & SelectionKey.OP_READ) != 0 && !up.ended() && !down.ended()) {
                down.move(woke);
            }
        }
    }

    /** The hub's time, if a pacing needs it. */
    private long now() {
        return timed ? clock.nanoTime() : 0;
    }

    private int readyOps(SelectionKey key) {
        return key.isValid() && selector.selectedKeys().contains(key) ? key.readyOps() : 0;
    }

    /** A channel is read while its direction has room, and written while bytes due for it wait. */
    private static int interest(boolean ended, Direction from, Direction to, long now) {
        int ops = !ended && from.pacing.room() > 0 ? SelectionKey.OP_READ : 0;
        return to.pacing.due(now) > 0 ? ops | SelectionKey.OP_WRITE : ops;
    }

    /**
     * Waits for the sockets, at most until something falls due: whole milliseconds on the
     * selector (rounded down, so it wakes no later than due), and the last fraction of a
     * millisecond parked, which the selector cannot wait for; rounding up instead made every hop
     * up to a millisecond late.
     */
    private void waitAtMost(long nanos) throws IOException {
        if (nanos == 0) {
            selector.selectNow();
        } else if (nanos == Long.MAX_VALUE) {
            selector.select();
        } else if (nanos >= 1_000_000) {
            selector.select(TimeUnit.NANOSECONDS.toMillis(nanos));
        } else {
            LockSupport.parkNanos(nanos);
            selector.selectNow();
        }
    }

    /**
     * Ends both streams without a reset once everything read is written: shuts down both outputs
     * (the end of stream follows what is queued), then reads and drops what either side still
     * sends until both have ended or {@link #FINISH_NS} has passed on the hub's clock. Closing a
     * socket with unread input would reset the connection, and a reset throws away what is still
     * queued for that side.
     */
    private void finish() throws IOException {
        shutdownOutput(up.in);
        shutdownOutput(down.in);
        sourceKey.interestOps(up.ended() ? 0 : SelectionKey.OP_READ);
        targetKey.interestOps(down.ended() ? 0 : SelectionKey.OP_READ);
        long deadline = clock.nanoTime() + FINISH_NS;
        while (!(up.ended() && down.ended()) && !link.isClosed()) {
            long left = TimeUnit.NANOSECONDS.toMillis(deadline - clock.nanoTime());
            if (left <= 0) {
                LOG.fine(() -> link + ": a side did not end its stream in time; closing");
                return;
            }
            selector.select(left);
            selector.selectedKeys().clear();
            if (!up.ended() && up.drop()) {
                sourceKey.interestOps(0);
            }
            if (!down.ended() && down.drop()) {
                targetKey.interestOps(0);
            }
        }
    }

    /** Sends the end of stream after what is queued; a side that reset has no stream left to end. */
    private static void shutdownOutput(SocketChannel channel) {
        try {
            channel.shutdownOutput();
        } catch (IOException e) {
            // Reset or already closed: nothing to end.
        }
    }
}
