package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;

/**
 * A WSS port while it listens: a blocking server socket and the thread that accepts on it and
 * hands each connection to the hub. Closing it stops the listening at once: a blocking channel's
 * socket is released by close() itself, whereas one registered with a Selector is released only
 * when that selector next runs, which would let a connect through after a break.
 */
final class PortListener implements Runnable {

    private static final Logger LOG = Logger.getLogger(PortListener.class.getName());
    private static final int BACKLOG = 128;
    private static final long CLOSE_WAIT_NS = TimeUnit.SECONDS.toNanos(1);

    private final Hub hub;
    private final WssPort port;
    private final ServerSocketChannel channel;
    /** The thread is inside accept(), where it holds the socket open. */
    private boolean inAccept;

    PortListener(Hub hub, WssPort port, ServerSocketChannel channel) {
        this.hub = hub;
        this.port = port;
        this.channel = channel;
    }

    /** A blocking server socket bound to the address (port 0: the OS chooses). */
    static ServerSocketChannel bind(InetSocketAddress address) throws IOException {
        ServerSocketChannel channel = ServerSocketChannel.open();
        try {
            channel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            channel.bind(address, BACKLOG);
            return channel;
        } catch (IOException e) {
            channel.close();
            throw e;
        }
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
        Closing.quietly(channel);
        long deadline = System.nanoTime() + CLOSE_WAIT_NS;
        synchronized (this) {
            while (inAccept) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    LOG.warning(port + ": the accepting thread did not stop in time");
                    return;
                }
                try {
                    TimeUnit.NANOSECONDS.timedWait(this, left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
        }
    }

    private synchronized void accepting(boolean now) {
        inAccept = now;
        if (!now) {
            notifyAll();
        }
    }

    @Override
    public void run() {
        while (channel.isOpen()) {
            SocketChannel socket;
            accepting(true);
            try {
                socket = channel.accept();
            } catch (IOException e) {
                accepting(false);
                if (!channel.isOpen()) {
                    return;
                }
                // Out of descriptors, say: the port still listens, so try again in a moment.
                hub.warnings.warn(LOG, "failed accepts", channel.socket().getInetAddress(),
                        port + ": accept failed, trying again: " + e);
                Pause.briefly();
                continue;
            }
            accepting(false);
            hub.accepted(port, this, socket);
        }
    }
}
