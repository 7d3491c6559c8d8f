package org.usarsim.wss.world;

import java.io.IOException;
import java.net.Socket;
import java.util.logging.Logger;

/**
 * A client of one of the world server's listening sockets (USARSim's positions, rosbridge) on a
 * thread of its own: started, closed from another thread, waited for. {@link ServedClients}
 * keeps them.
 */
abstract class ClientThread implements Runnable {

    private static final Logger LOG = Logger.getLogger(ClientThread.class.getName());

    final Socket socket;
    /** Its address and port, {@code 127.0.0.1:51420}, for the log. */
    final String peer;
    private final String threadName;
    /** Its thread, once {@link #start} started it. */
    private volatile Thread thread;

    /** @param threadName its thread's name before the peer ({@code world-client}) */
    ClientThread(Socket socket, String threadName) {
        this.socket = socket;
        this.peer = socket.getInetAddress().getHostAddress() + ":" + socket.getPort();
        this.threadName = threadName;
    }

    void start() {
        Thread started = new Thread(this, threadName + " " + peer);
        started.setDaemon(true);
        thread = started;
        started.start();
    }

    /** Waits, until {@code deadline} ({@link System#nanoTime()}) at most, for its thread to end. */
    void awaitEnd(long deadline) throws InterruptedException {
        Thread started = thread;
        long left = deadline - System.nanoTime();
        if (started != null && left > 0) {
            started.join(Math.max(1, left / 1_000_000));
        }
    }

    /** Closes its connection, which ends its thread's reading. */
    void close() {
        try {
            socket.close();
        } catch (IOException e) {
            LOG.fine(() -> "closing the connection of client " + peer + ": " + e);
        }
    }
}
