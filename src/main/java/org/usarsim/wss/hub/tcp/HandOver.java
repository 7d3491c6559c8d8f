package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.InetAddress;
import java.nio.channels.SocketChannel;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * The thread that hands what the {@link PortSelector} accepted to the hub, in the order it was
 * accepted ({@code wss-port-handover}). The selector's thread never calls the hub: the hub may
 * wait for the selector (a break waits for its ports to close), and the hub's work on an accepted
 * connection asks the model and takes the hub's lock. So the selector only queues, and this
 * thread calls {@link LinkHub#accepted}; a listener's end comes through the same queue, after
 * every connection it accepted, which is what a departure's drain waits for.
 *
 * <p>The queue never refuses (the selector must never wait for it); the selector stops accepting
 * while it holds {@link #HIGH_WATER} connections, and those wait in the kernel's queues, as they
 * would for a busy thread of its own.
 */
final class HandOver implements Runnable {

    private static final Logger LOG = Logger.getLogger(HandOver.class.getName());
    /** Connections queued at which the selector stops accepting until the queue is down to {@link #LOW_WATER}. */
    static final int HIGH_WATER = 1024;
    static final int LOW_WATER = 256;

    /** One thing to hand over: a connection a listener accepted, its end, or a failed accept. */
    private record Item(PortListener listener, SocketChannel connection, IOException failure) {
    }

    private static final Item STOP = new Item(null, null, null);

    private final LinkHub hub;
    private final PortSelector selector;
    private final LinkedBlockingQueue<Item> queue = new LinkedBlockingQueue<>();
    private final AtomicInteger connections = new AtomicInteger();
    /** A failed accept waits to be reported: at most one at a time is queued. */
    private final AtomicBoolean failureQueued = new AtomicBoolean();

    HandOver(LinkHub hub, PortSelector selector) {
        this.hub = hub;
        this.selector = selector;
    }

    /** Connections queued, not yet handed over. */
    int backlog() {
        return connections.get();
    }

    void accepted(PortListener listener, SocketChannel connection) {
        connections.incrementAndGet();
        queue.add(new Item(listener, connection, null));
    }

    /** The listener is closed: once what it accepted before is handed over, it has ended. */
    void ended(PortListener listener) {
        queue.add(new Item(listener, null, null));
    }

    /** An accept failed (out of descriptors, say): the hub may give some back; otherwise it is reported. */
    void acceptFailed(PortListener listener, IOException failure) {
        if (failureQueued.compareAndSet(false, true)) {
            queue.add(new Item(listener, null, failure));
        }
    }

    void stop() {
        queue.add(STOP);
    }

    @Override
    public void run() {
        while (true) {
            Item item;
            try {
                item = queue.take();
            } catch (InterruptedException e) {
                continue; // stopped only by STOP: what is queued must be handed over or closed
            }
            if (item == STOP) {
                closeQueued();
                return;
            }
            if (item.connection() != null) {
                if (connections.decrementAndGet() == LOW_WATER) {
                    selector.acceptAgain();
                }
                handOver(item.listener(), item.connection());
            } else if (item.failure() != null) {
                failureQueued.set(false);
                reportFailure(item.listener(), item.failure());
            } else {
                item.listener().ended();
            }
        }
    }

    private void handOver(PortListener listener, SocketChannel connection) {
        try {
            hub.accepted(listener.port, listener.epoch, connection);
        } catch (Throwable e) {
            // As net.AcceptLoop's policy: the connection is dropped alone, and said.
            InetAddress peer = connection.socket().getInetAddress();
            String from = peer == null ? "?" : peer.getHostAddress() + ":" + connection.socket().getPort();
            Closing.quietly(connection);
            if (e instanceof VirtualMachineError && !(e instanceof OutOfMemoryError)) {
                LOG.log(Level.SEVERE, "cannot serve a connection on " + listener.port + " from " + from + " (" + e + "): the WSS ports stop listening", e);
                selector.close(); // clients are refused rather than left waiting
                throw (VirtualMachineError) e;
            }
            hub.warn(LOG, "connections not served", peer, "cannot serve a connection on " + listener.port + " from " + from
                    + " (" + e + "): dropped it; accepting the next", e);
        }
    }

    private void reportFailure(PortListener listener, IOException failure) {
        if (hub.descriptors().gaveBack(failure)) {
            return; // some were given back: the port accepts again after its pause
        }
        InetAddress address = listener.channel.socket().getInetAddress();
        hub.warn(LOG, "failed accepts", address, listener.port + ": accept failed, trying again: " + failure, null);
    }

    /** At the end: connections never handed over are closed, and every listener waited for has ended. */
    private void closeQueued() {
        Item item;
        while ((item = queue.poll()) != null) {
            if (item.connection() != null) {
                Closing.quietly(item.connection());
            } else if (item.listener() != null) {
                item.listener().ended();
            }
        }
    }
}
