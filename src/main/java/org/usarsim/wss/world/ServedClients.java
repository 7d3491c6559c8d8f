package org.usarsim.wss.world;

import java.io.IOException;
import java.nio.channels.ServerSocketChannel;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.logging.Logger;

/**
 * The clients of one of the world server's listening sockets, each on its own thread: the one
 * rule for taking a new one, forgetting one that left, and closing them all with the socket.
 */
final class ServedClients<C extends ClientThread> {

    private static final Logger LOG = Logger.getLogger(ServedClients.class.getName());

    private final Set<C> clients = ConcurrentHashMap.newKeySet();

    /**
     * Takes a new client: counted, then its thread started by {@code starter} ({@link ClientThread#start},
     * or what a test puts in its place); closed at once when the socket no longer listens. When
     * starting throws, the client is forgotten and the accept loop's policy applies.
     */
    void serve(C client, ServerSocketChannel listening, Consumer<C> starter) {
        clients.add(client);
        if (!listening.isOpen()) {
            client.close();
        }
        try {
            starter.accept(client);
        } catch (Throwable e) {
            clients.remove(client);
            throw e;
        }
    }

    void ended(C client) {
        clients.remove(client);
    }

    int size() {
        return clients.size();
    }

    /**
     * Stops listening at once (the socket is released only when the thread blocked in accept()
     * has let go of it: waited for, a second at most), then closes every client and waits, a
     * second at most in all, for their threads to end, so that their "left" lines come before the
     * server's "stopped".
     */
    void closeAll(ServerSocketChannel listening, Thread acceptor) {
        try {
            listening.close();
        } catch (IOException e) {
            LOG.fine(() -> "closing a listening socket: " + e);
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
    }
}
