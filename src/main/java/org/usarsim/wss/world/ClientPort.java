package org.usarsim.wss.world;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.net.AcceptLoop;
import org.usarsim.wss.net.LogLimiter;

/**
 * One of the world server's listening sockets (USARSim's positions, rosbridge) with its
 * accepting thread and its clients, each on a thread of its own: the one rule for taking a new
 * client, forgetting one that left, and closing them all with the socket; and the limit on the
 * log lines its clients cause. Accepting follows {@link AcceptLoop}'s policy.
 */
final class ClientPort<C extends ClientThread> {

    /** Makes the client of a new connection, told how many are being served already. */
    interface Clients<C> {
        C client(Socket socket, int serving);
    }

    private final Logger log;
    private final String name;
    private final ServerSocketChannel server;
    private final Set<C> clients = ConcurrentHashMap.newKeySet();
    private final Thread acceptor;
    private final AtomicBoolean closed = new AtomicBoolean();
    /** The limit on the lines its clients cause (connected, left, a bad request). */
    final LogLimiter lines;

    /**
     * Binds; accepting starts with {@link #start} (once the server that owns it has it: its
     * clients reach the server's fields).
     *
     * @param thread its accepting thread's name before the port ({@code world-server}); its limit's
     *        thread is this with {@code -warnings}
     * @param name what listens, for the log ({@code world server}: "the world server stops listening",
     *        "world server stopped")
     * @param what what a connection is, for the log ({@code client})
     * @param starter starts a client's thread: {@link ClientThread#start}, or what a test puts in its place
     * @throws IOException the address and port cannot be bound
     */
    ClientPort(InetSocketAddress address, String thread, Logger log, String name, String what, Clients<C> make,
            Consumer<C> starter) throws IOException {
        this.log = log;
        this.name = name;
        this.server = AcceptLoop.bind(address, AcceptLoop.BACKLOG);
        this.lines = LogLimiter.standard(thread + "-warnings");
        this.acceptor = new Thread(new Acceptor(what, make, starter), thread + " " + port());
        acceptor.setDaemon(true);
    }

    /** Starts accepting. */
    void start() {
        acceptor.start();
    }

    int port() {
        return server.socket().getLocalPort();
    }

    int size() {
        return clients.size();
    }

    void ended(C client) {
        clients.remove(client);
    }

    /**
     * Stops listening at once (the socket is released only when the thread blocked in accept()
     * has let go of it: waited for, a second at most), then closes every client and waits, a
     * second at most in all, for their threads to end, so that their "left" lines come before
     * "NAME stopped"; once only.
     */
    void close() {
        // Not server.isOpen(): the acceptor closes the socket itself when it gives up (AcceptLoop).
        if (!closed.compareAndSet(false, true)) {
            return;
        }
        try {
            server.close();
        } catch (IOException e) {
            log.fine(() -> "closing a listening socket: " + e);
        }
        try {
            acceptor.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        List<C> closing = List.copyOf(clients);
        closing.forEach(ClientThread::close);
        long deadline = System.nanoTime() + 1_000_000_000L;
        try {
            for (C client : closing) {
                client.awaitEnd(deadline);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        lines.close();
        log.info(name + " stopped");
    }

    /** The accepting loop: gives each client its thread, with {@link AcceptLoop}'s policy when that fails. */
    private final class Acceptor extends AcceptLoop {

        private final String what;
        private final Clients<C> make;
        private final Consumer<C> starter;

        Acceptor(String what, Clients<C> make, Consumer<C> starter) {
            super(ClientPort.this.server, log, "the " + ClientPort.this.name, what);
            this.what = what;
            this.make = make;
            this.starter = starter;
        }

        /**
         * Takes a new client: counted, then its thread started; closed at once when the socket no
         * longer listens. When starting throws, the client is forgotten and the loop's policy applies.
         */
        @Override
        protected void serve(SocketChannel socket) {
            C client = make.client(socket.socket(), clients.size());
            clients.add(client);
            if (!server.isOpen()) {
                client.close();
            }
            try {
                starter.accept(client);
            } catch (Throwable e) {
                clients.remove(client);
                throw e;
            }
        }

        @Override
        protected boolean acceptFailed(IOException e) {
            // Out of descriptors, say: clients must still be able to connect once it passes.
            log.log(Level.SEVERE, "accepting a " + what + " failed, trying again: " + e, e);
            return false;
        }
    }
}
