package org.usarsim.wss.net;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.Channel;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * A blocking server socket and the loop that accepts on it until it is closed: the hub's control
 * port, each listening WSS port and the world server. One policy for all of them:
 * <ul>
 * <li>an accept that fails while the socket is open (out of descriptors, say) is reported by
 * {@link #acceptFailed}, and the loop tries again after {@link #PAUSE_MS}, so that clients can
 * connect again once it passes (at once when {@link #acceptFailed} removed the cause);</li>
 * <li>a connection that {@link #serve} cannot take (its thread cannot start: an OutOfMemoryError
 * "unable to create native thread") is closed alone, with a WARNING, and the loop goes on;</li>
 * <li>a VirtualMachineError other than an OutOfMemoryError leaves the JVM in doubt: the socket
 * is closed too, so that clients are refused rather than left waiting on a bound port, and the
 * error goes on up.</li>
 * </ul>
 */
public abstract class AcceptLoop implements Runnable {

    /** How long the loop waits before accepting again after a failed accept. */
    static final long PAUSE_MS = 100;
    /**
     * The accept queue of a port many clients connect to at once (the hub's control port, the
     * world server): a whole team starts at once, and a SYN that finds the queue full is dropped
     * and retransmitted only a second later. The OS caps it at net.core.somaxconn (4,096 on
     * current Linux; docs/reliability.md, "Accept queue").
     */
    public static final int BACKLOG = 1024;

    protected final ServerSocketChannel server;
    private final Logger log;
    private final String name;
    private final String what;

    /**
     * @param name what listens, for the log ("the world server")
     * @param what what a connection is, put before its address in the log ("client")
     */
    protected AcceptLoop(ServerSocketChannel server, Logger log, String name, String what) {
        this.server = server;
        this.log = log;
        this.name = name;
        this.what = what;
    }

    /** A blocking server socket bound to the address (port 0: the OS chooses), SO_REUSEADDR set. */
    public static ServerSocketChannel bind(InetSocketAddress address, int backlog) throws IOException {
        ServerSocketChannel channel = ServerSocketChannel.open();
        try {
            channel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            channel.bind(address, backlog);
            return channel;
        } catch (IOException e) {
            channel.close();
            throw e;
        }
    }

    /** Waits for the next connection; a subclass may wrap it (note that the thread is in accept()). */
    protected SocketChannel accept() throws IOException {
        return server.accept();
    }

    /**
     * Hands a new connection over, normally to a thread of its own. When it throws, it has undone
     * what it started; the loop closes the connection and applies its policy.
     */
    protected abstract void serve(SocketChannel connection);

    /**
     * Reports an accept that failed while the socket is open, or removes its cause.
     *
     * @return true when the cause is gone (descriptors were given back): the loop tries again at
     *         once; false: it pauses first
     */
    protected abstract boolean acceptFailed(IOException e);

    @Override
    public void run() {
        while (server.isOpen()) {
            SocketChannel connection;
            try {
                connection = accept();
            } catch (IOException e) {
                if (!server.isOpen()) {
                    return;
                }
                if (!acceptFailed(e)) {
                    pause();
                }
                continue;
            }
            try {
                serve(connection);
            } catch (Throwable e) {
                dropped(connection, e);
            }
        }
    }

    private void dropped(SocketChannel connection, Throwable e) {
        String peer = connection.socket().getInetAddress().getHostAddress() + ":" + connection.socket().getPort();
        close(connection, e);
        if (e instanceof VirtualMachineError && !(e instanceof OutOfMemoryError)) {
            log.log(Level.SEVERE, "cannot serve " + what + " " + peer + " (" + e + "): " + name + " stops listening", e);
            close(server, e);
            throw (VirtualMachineError) e;
        }
        warnDropped(connection.socket().getInetAddress(),
                "cannot serve " + what + " " + peer + " (" + e + "): dropped it; accepting the next", e);
    }

    /** Writes the WARNING for a connection dropped because it could not be served; a subclass may limit it. */
    protected void warnDropped(InetAddress peer, String message, Throwable e) {
        log.log(Level.WARNING, message, e);
    }

    private static void close(Channel channel, Throwable failure) {
        try {
            channel.close();
        } catch (IOException closing) {
            failure.addSuppressed(closing);
        }
    }

    private static void pause() {
        try {
            Thread.sleep(PAUSE_MS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
