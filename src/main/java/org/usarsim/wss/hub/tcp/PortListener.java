package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.SelectionKey;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.hub.core.WssPort;

/**
 * One listening of a WSS port: its listening socket, the core's epoch it listens with, and its
 * key in the {@link PortSelector}. It is closed on the selector's thread, the only one that
 * touches its key: a channel registered with a Selector is really closed (its descriptor given
 * back, its accept queue reset) only when that selector next runs, so a close is done once the
 * selector has run after it ({@link #awaitClosed}).
 *
 * <p>A departure drains it first ({@link #beginDrain}): the hub connects to the port itself, the
 * selector's thread accepts until that marker, then accepts no more (the socket stays open and
 * holds the number until the departure stops the port, which resets whatever came after), and the
 * hand-over thread says the drain ended once it has handed every connection before the marker to
 * the hub.
 */
public final class PortListener {

    private static final Logger LOG = Logger.getLogger(PortListener.class.getName());

    final WssPort port;
    /** Which listening of the port this is (the core's epoch): a connection it accepted after the port stopped is refused. */
    final int epoch;
    final ServerSocketChannel channel;
    /** The hub's clock, which the deadlines of the waits for it are on. */
    private final HubClock clock;
    /** Its key in the selector; only the selector's thread reads or writes it. */
    SelectionKey key;
    /** Asked to close (a stop or a release); the selector's thread closes it. */
    private volatile boolean closing;
    /** The drain's marker was reached: accepting no more. Only the selector's thread writes it. */
    private volatile boolean drained;
    /** Counted down once the socket is really closed (the selector ran after the close). */
    private final CountDownLatch closed = new CountDownLatch(1);
    /** Counted down once the hand-over thread handed every connection this listener accepted to the hub. */
    private final CountDownLatch ended = new CountDownLatch(1);
    /** The local address of the hub's own connection that marks the end of a drain; null when not draining. */
    private volatile InetSocketAddress markerAddress;
    private SocketChannel marker;

    PortListener(WssPort port, int epoch, ServerSocketChannel channel, HubClock clock) {
        this.port = port;
        this.epoch = epoch;
        this.channel = channel;
        this.clock = clock;
    }

    /** Whether its close was asked for (it may not be done yet: {@link #isClosed}). */
    boolean isClosing() {
        return closing;
    }

    boolean isClosed() {
        return closed.getCount() == 0;
    }

    /** On the selector's thread: closes the channel; it is really closed once the selector has run again ({@link #closedNow}). */
    void close() {
        closing = true;
        if (key != null) {
            key.cancel();
        }
        Closing.quietly(channel);
    }

    /** On the selector's thread, once it ran after {@link #close}: the socket no longer listens. */
    void closedNow() {
        closing = true;
        closed.countDown();
        Closing.quietly(marker());
    }

    /**
     * On the selector's thread: the drain's marker was accepted (and reset), so everything before
     * it is queued for the hub; this listener accepts no more. The hub's own end of the marker
     * is closed now (the reset reached it: no TIME_WAIT is left).
     */
    void drained() {
        drained = true;
        if (key != null) {
            key.cancel();
        }
        Closing.quietly(marker());
    }

    /** Whether the drain's marker was reached: it accepts no more, and waits for the port to stop. */
    boolean isDrained() {
        return drained;
    }

    /** On the hand-over thread: every connection accepted before the close has been handed to the hub. */
    void ended() {
        ended.countDown();
    }

    /** Waits until the socket no longer listens, at most until the deadline (the hub's clock). @return whether it is closed */
    boolean awaitClosed(long deadline) {
        return await(closed, deadline);
    }

    /**
     * Starts stopping the way a robot's departure stops a port: every connection the kernel has
     * already completed is handed to the hub, then the socket closes. The accept queue is first
     * in, first out, so the hub connects to the port itself and the selector's thread stops at
     * that connection ({@link #awaitEnd}).
     *
     * @param address where the port is reached from this machine
     * @return false when the hub's own connection could not be started; the stop then closes the port
     */
    synchronized boolean beginDrain(InetAddress address) {
        if (marker != null || closing) {
            return marker != null;
        }
        SocketChannel connection = null;
        try {
            connection = SocketChannel.open();
            connection.configureBlocking(false);
            connection.bind(new InetSocketAddress(address, 0)); // its address is known before the connect completes
            markerAddress = (InetSocketAddress) connection.getLocalAddress();
            connection.connect(new InetSocketAddress(address, port.number));
            marker = connection;
            return true;
        } catch (IOException e) {
            LOG.fine(() -> port + ": could not drain before stopping: " + e);
            markerAddress = null;
            Closing.quietly(connection);
            return false;
        }
    }

    private synchronized SocketChannel marker() {
        return marker;
    }

    /** Whether the connection is the hub's own that ends a drain. */
    boolean isMarker(SocketChannel socket) {
        InetSocketAddress address = markerAddress;
        if (address == null) {
            return false;
        }
        try {
            return address.equals(socket.getRemoteAddress());
        } catch (IOException e) {
            return false;
        }
    }

    /** Closes the drain's marker, accepted: a reset rather than a close leaves no TIME_WAIT on the port's number. */
    static void reset(SocketChannel socket) {
        try {
            socket.setOption(StandardSocketOptions.SO_LINGER, 0);
        } catch (IOException e) {
            // Closed already: nothing lingers.
        }
        Closing.quietly(socket);
    }

    /** Waits until the drain ended (or the listener closed and its connections were handed over), or until the deadline (the hub's clock). */
    public void awaitEnd(long deadline) {
        if (!await(ended, deadline)) {
            LOG.fine(() -> port + ": did not drain in time");
        }
    }

    private boolean await(CountDownLatch latch, long deadline) {
        try {
            long left;
            while ((left = deadline - clock.nanoTime()) > 0) {
                if (latch.await(clock.waitNanos(left), TimeUnit.NANOSECONDS)) {
                    return true;
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return latch.getCount() == 0;
    }

    @Override
    public String toString() {
        return port + " (listening " + epoch + ")";
    }
}
