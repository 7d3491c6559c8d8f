package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.logging.Level;
import java.util.logging.Logger;

/** Accepts control connections and runs a {@link ControlSession} thread for each. */
final class ControlListener implements Runnable {

    private static final Logger LOG = Logger.getLogger(ControlListener.class.getName());
    /**
     * Connections the OS completes before the listener accepts them. A whole team starts at once:
     * a SYN that finds the queue full is dropped and retransmitted only a second later. The OS
     * caps it at net.core.somaxconn (4,096 on current Linux; docs/reliability.md).
     */
    static final int BACKLOG = 1024;

    private final Hub hub;
    private final ServerSocketChannel server;
    private final Set<ControlSession> sessions = ConcurrentHashMap.newKeySet();
    private final Thread thread;

    /** Binds at once, so that a port in use is known before anything else starts. */
    ControlListener(Hub hub, InetSocketAddress address) throws IOException {
        this.hub = hub;
        this.server = ServerSocketChannel.open();
        try {
            server.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            server.bind(address, BACKLOG);
        } catch (IOException e) {
            server.close();
            throw e;
        }
        this.thread = new Thread(this, "wss-control-listener");
        thread.setDaemon(true);
    }

    int port() {
        return server.socket().getLocalPort();
    }

    void start() {
        thread.start();
    }

    void close() {
        Closing.quietly(server);
        sessions.forEach(ControlSession::close);
    }

    List<SocketChannel> channels() {
        return sessions.stream().map(ControlSession::channel).toList();
    }

    void ended(ControlSession session) {
        sessions.remove(session);
    }

    @Override
    public void run() {
        while (server.isOpen()) {
            SocketChannel channel;
            try {
                channel = server.accept();
            } catch (IOException e) {
                if (!server.isOpen()) {
                    return;
                }
                // Out of descriptors, say: robots must still be able to connect once it passes.
                LOG.log(Level.SEVERE, "accepting a control connection failed, trying again: " + e, e);
                Pause.briefly();
                continue;
            }
            ControlSession session = new ControlSession(hub, this, channel);
            sessions.add(session);
            if (!server.isOpen()) {
                session.close();
            }
            try {
                session.start();
            } catch (OutOfMemoryError e) {
                LOG.severe("no thread for the control connection from " + channel.socket().getInetAddress() + ": " + e);
                session.close();
                sessions.remove(session);
            }
        }
    }
}
