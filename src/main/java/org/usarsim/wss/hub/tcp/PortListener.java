package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.net.AcceptLoop;

/**
 * A WSS port while it listens: a blocking server socket and the thread that accepts on it and
 * hands each connection to the hub. Closing it stops the listening at once: a blocking channel's
 * socket is released by close() itself, whereas one registered with a Selector is released only
 * when that selector next runs, which would let a connect through after a break. The loop and
 * its policy for failures are {@link AcceptLoop}'s; what is a WSS port's own (the close that waits
 * for accept() to return, the drain) is here.
 */
public final class PortListener extends AcceptLoop {

    private static final Logger LOG = Logger.getLogger(PortListener.class.getName());
    private static final int BACKLOG = 128;
    private static final long CLOSE_WAIT_NS = TimeUnit.SECONDS.toNanos(1);

    private final Switchboard switchboard;
    private final WssPort port;
    /** Which listening of the port this is (the core's epoch): a connection it accepts after the port stopped is refused. */
    private final int epoch;
    /** The thread is inside accept(), where it holds the socket open. */
    private boolean inAccept;
    /** The hub's own connection that marks the end of what is drained (see {@link #beginDrain}). */
    private SocketChannel marker;
    private InetSocketAddress markerAddress;
    /** The thread has stopped: it will hand the hub no more connections. */
    private boolean ended;

    PortListener(Switchboard switchboard, WssPort port, int epoch, ServerSocketChannel channel) {
        super(channel, LOG, port.toString(), "a connection on " + port + " from");
        this.switchboard = switchboard;
        this.port = port;
        this.epoch = epoch;
    }

    /** A blocking server socket bound to the address (port 0: the OS chooses). */
    static ServerSocketChannel bind(InetSocketAddress address) throws IOException {
        return AcceptLoop.bind(address, BACKLOG);
    }

    void start() {
        Thread thread = new Thread(this, "wss-port " + port.number);
        thread.setDaemon(true);
        thread.start();
    }

    /**
     * Stops listening, and returns once the socket no longer listens. Closing a channel whose
     * thread is blocked in accept() only signals that thread; the socket is released when its
     * accept() returns, so wait for that (it does not need the hub's lock, so this may be called
     * under it).
     */
    void close() {
        Closing.quietly(server);
        if (!await(() -> !inAccept, System.nanoTime() + CLOSE_WAIT_NS)) {
            LOG.warning(port + ": the accepting thread did not stop in time");
        }
    }

    /** Waits on this listener's monitor until the condition holds or the deadline (System.nanoTime()) passes. */
    private synchronized boolean await(BooleanSupplier condition, long deadline) {
        while (!condition.getAsBoolean()) {
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                return false;
            }
            try {
                TimeUnit.NANOSECONDS.timedWait(this, left);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }
        return true;
    }

    /**
     * Starts stopping the way a robot's departure stops a port: every connection the kernel has
     * already completed is handed to the hub, then the socket closes. A socket that closes
     * throws away its accept queue, and the thread blocked in accept() can only be woken by a
     * connection or a close; so the hub connects to the port itself, and the thread, taking
     * connections in the order they were completed, stops at that one ({@link #awaitEnd}).
     *
     * @param address where the port is reached from this machine
     * @return false when the hub's own connection could not be started; close() then stops the port
     */
    synchronized boolean beginDrain(InetAddress address) {
        if (marker != null || ended || !server.isOpen()) {
            return marker != null;
        }
        SocketChannel connection = null;
        try {
            connection = SocketChannel.open();
            connection.configureBlocking(false);
            connection.bind(new InetSocketAddress(address, 0)); // its address is known before the connect completes
            connection.connect(new InetSocketAddress(address, port.number));
            markerAddress = (InetSocketAddress) connection.getLocalAddress();
            marker = connection;
            return true;
        } catch (IOException e) {
            LOG.fine(() -> port + ": could not drain before stopping: " + e);
            Closing.quietly(connection);
            return false;
        }
    }

    /** Waits until the thread has stopped, or until the deadline (System.nanoTime()). */
    public void awaitEnd(long deadline) {
        if (!await(() -> ended, deadline)) {
            LOG.fine(() -> port + ": did not drain in time");
        }
    }

    private synchronized boolean isMarker(SocketChannel socket) {
        try {
            return markerAddress != null && markerAddress.equals(socket.getRemoteAddress());
        } catch (IOException e) {
            return false;
        }
    }

    private static void resetQuietly(SocketChannel socket) {
        try {
            socket.setOption(StandardSocketOptions.SO_LINGER, 0);
        } catch (IOException e) {
            // Closed already: nothing lingers.
        }
        Closing.quietly(socket);
    }

    private synchronized void end() {
        ended = true;
        Closing.quietly(marker);
        notifyAll();
    }

    private synchronized void accepting(boolean now) {
        inAccept = now;
        if (!now) {
            notifyAll();
        }
    }

    @Override
    public void run() {
        try {
            super.run();
        } finally {
            end();
        }
    }

    @Override
    protected SocketChannel accept() throws IOException {
        accepting(true);
        try {
            return super.accept();
        } finally {
            accepting(false);
        }
    }

    @Override
    protected void serve(SocketChannel socket) {
        if (isMarker(socket)) {
            // Everything completed before the drain began is handed over: stop here. A reset
            // rather than a close leaves no TIME_WAIT on the port's number.
            resetQuietly(socket);
            Closing.quietly(server);
            return;
        }
        switchboard.accepted(port, epoch, socket);
    }

    @Override
    protected void acceptFailed(IOException e) {
        // Out of descriptors, say: the port still listens, so try again in a moment.
        switchboard.warn(LOG, "failed accepts", server.socket().getInetAddress(), port + ": accept failed, trying again: " + e, null);
    }

    @Override
    protected void warnDropped(InetAddress peer, String message, Throwable e) {
        switchboard.warn(LOG, "connections not served", peer, message, e);
    }
}
