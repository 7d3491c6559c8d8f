package org.usarsim.wss.hub;

import java.io.IOException;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.logging.Level;
import java.util.logging.Logger;

/** One thread that accepts connections on every listening WSS port and hands them to the hub. */
final class PortAcceptor implements Runnable {

    private static final Logger LOG = Logger.getLogger(PortAcceptor.class.getName());

    private record Registration(ServerSocketChannel channel, WssPort port) {
    }

    private final Hub hub;
    private final Selector selector;
    private final Queue<Registration> pending = new ConcurrentLinkedQueue<>();
    private final Thread thread;

    PortAcceptor(Hub hub) throws IOException {
        this.hub = hub;
        this.selector = Selector.open();
        this.thread = new Thread(this, "wss-port-acceptor");
        thread.setDaemon(true);
    }

    void start() {
        thread.start();
    }

    /** Starts accepting on the port's current channel (it may be closed by then; that is fine). */
    void add(WssPort port) {
        pending.add(new Registration(port.channel(), port));
        selector.wakeup();
    }

    void close() {
        Closing.quietly(selector);
    }

    @Override
    public void run() {
        try {
            while (selector.isOpen()) {
                selector.select();
                registerPending();
                for (SelectionKey key : selector.selectedKeys()) {
                    accept(key);
                }
                selector.selectedKeys().clear();
            }
        } catch (ClosedSelectorException e) {
            // The hub is closing.
        } catch (IOException e) {
            LOG.log(Level.SEVERE, "the WSS port acceptor failed: " + e, e);
        }
    }

    private void registerPending() {
        Registration registration;
        while ((registration = pending.poll()) != null) {
            try {
                registration.channel().register(selector, SelectionKey.OP_ACCEPT, registration.port());
            } catch (ClosedChannelException e) {
                // It stopped listening before we got to it.
            }
        }
    }

    private void accept(SelectionKey key) {
        if (!key.isValid()) {
            return;
        }
        ServerSocketChannel channel = (ServerSocketChannel) key.channel();
        WssPort port = (WssPort) key.attachment();
        try {
            SocketChannel socket;
            while ((socket = channel.accept()) != null) {
                hub.accepted(port, socket);
            }
        } catch (IOException e) {
            key.cancel();
            if (channel.isOpen()) {
                LOG.warning(port + ": accept failed: " + e);
            }
        }
    }
}
