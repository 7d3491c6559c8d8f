package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.SocketChannel;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.net.AcceptLoop;

/** Accepts control connections and runs a {@link ControlSession} thread for each. */
public final class ControlListener extends AcceptLoop {

    private static final Logger LOG = Logger.getLogger(ControlListener.class.getName());

    private final ControlHub hub;
    private final Set<ControlSession> sessions = ConcurrentHashMap.newKeySet();
    private final Thread thread;

    /**
     * Binds the address for a moment: a control port in use, or an address not of this machine,
     * is known before anything else starts (the model, the fixed ports), though the hub binds the
     * control port last. A number taken in between is still refused by the bind.
     */
    public static void checkFree(InetSocketAddress address) throws IOException {
        AcceptLoop.bind(address, 1).close();
    }

    /** Binds at once: connections are accepted (by the kernel, then by {@link #start}) from now on. */
    public ControlListener(ControlHub hub, InetSocketAddress address) throws IOException {
        super(AcceptLoop.bind(address, AcceptLoop.BACKLOG), LOG, "the control port", "the control connection from");
        this.hub = hub;
        this.thread = new Thread(this, "wss-control-listener");
        thread.setDaemon(true);
    }

    public int port() {
        return server.socket().getLocalPort();
    }

    public void start() {
        thread.start();
    }

    /**
     * Closes the control port and every control connection. A thread blocked in accept() keeps the
     * socket listening until it returns: close waits for it (at most a second), so that the port
     * is free when close returns.
     */
    public void close() {
        Closing.quietly(server);
        sessions.forEach(ControlSession::close);
        if (thread.isAlive() && thread != Thread.currentThread()) {
            try {
                thread.join(1000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    public List<SocketChannel> channels() {
        return sessions.stream().map(ControlSession::channel).toList();
    }

    void ended(ControlSession session) {
        sessions.remove(session);
    }

    @Override
    protected void serve(SocketChannel channel) {
        ControlSession session = new ControlSession(hub, this, channel);
        sessions.add(session);
        if (!server.isOpen()) {
            session.close();
        }
        try {
            session.start();
        } catch (Throwable e) {
            session.close();
            sessions.remove(session);
            throw e;
        }
    }

    @Override
    protected boolean acceptFailed(IOException e) {
        // Out of descriptors: remembered ports of robots that left give theirs back first.
        if (hub.descriptors().gaveBack(e)) {
            return true;
        }
        // Otherwise robots must still be able to connect once it passes.
        LOG.log(Level.SEVERE, "accepting a control connection failed, trying again: " + e, e);
        return false;
    }

    @Override
    protected void warnDropped(InetAddress peer, String message, Throwable e) {
        hub.warn(LOG, "connections not served", peer, message, e);
    }
}
