package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;

/**
 * A link's forwarding loop on the link's own thread: its two directions, its selector and the
 * selection keys of both sockets, and the end both loops share ({@link #finish}). Which loop
 * runs is the link's choice: {@link UnshapedForwarding} (as fast as the machine goes) or
 * {@link ShapedForwarding} (wss.shaping = on).
 */
abstract sealed class Forwarding permits UnshapedForwarding, ShapedForwarding {

    private static final Logger LOG = Logger.getLogger(Link.class.getName());
    /** How long a finished link waits for both sides to end their streams. */
    private static final long FINISH_NS = TimeUnit.SECONDS.toNanos(5);

    final Link link;
    final Selector selector;
    /** From the source robot to the target robot, and back. */
    final Direction up;
    final Direction down;
    final SelectionKey sourceKey;
    final SelectionKey targetKey;

    Forwarding(Link link, Selector selector, Direction up, Direction down) throws IOException {
        this.link = link;
        this.selector = selector;
        this.up = up;
        this.down = down;
        this.sourceKey = up.in.register(selector, SelectionKey.OP_READ);
        this.targetKey = down.in.register(selector, SelectionKey.OP_READ);
    }

    /** Forwards until the link is closed or both streams have ended. */
    abstract void forward() throws IOException;

    /**
     * Ends both streams without a reset once everything read is written: shuts down both outputs
     * (the end of stream follows what is queued), then reads and drops what either side still
     * sends until both have ended or {@link #FINISH_NS} has passed. Closing a socket with unread
     * input would reset the connection, and a reset throws away what is still queued for that side.
     */
    final void finish() throws IOException {
        shutdownOutput(up.in);
        shutdownOutput(down.in);
        sourceKey.interestOps(up.ended() ? 0 : SelectionKey.OP_READ);
        targetKey.interestOps(down.ended() ? 0 : SelectionKey.OP_READ);
        long deadline = System.nanoTime() + FINISH_NS;
        while (!(up.ended() && down.ended()) && !link.isClosed()) {
            long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
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
