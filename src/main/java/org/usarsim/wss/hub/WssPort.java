package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.util.HashSet;
import java.util.Set;

/**
 * A port on the WSS machine for one {@link PortKey}. Its number is chosen by the OS when it is
 * first allocated and kept for the server's life; it listens or not as the hub decides.
 * All state is guarded by the hub's lock.
 */
final class WssPort {

    final PortKey key;
    final int number;
    /** The connections accepted here that are still open. */
    final Set<Link> links = new HashSet<>();
    private final Hub hub;
    private final InetAddress bindAddress;
    private PortListener listener;

    private WssPort(Hub hub, PortKey key, InetAddress bindAddress, int number) {
        this.hub = hub;
        this.key = key;
        this.bindAddress = bindAddress;
        this.number = number;
    }

    /** Binds a new OS-chosen port, listening on it or not. */
    static WssPort allocate(Hub hub, PortKey key, InetAddress bindAddress, boolean listen) throws IOException {
        ServerSocketChannel channel = PortListener.bind(new InetSocketAddress(bindAddress, 0));
        WssPort port = new WssPort(hub, key, bindAddress, channel.socket().getLocalPort());
        if (listen) {
            port.accept(channel);
        } else {
            channel.close();
        }
        return port;
    }

    boolean listening() {
        return listener != null;
    }

    /** Listens again on the same number. */
    void listen() throws IOException {
        if (listener == null) {
            accept(PortListener.bind(new InetSocketAddress(bindAddress, number)));
        }
    }

    private void accept(ServerSocketChannel channel) {
        listener = new PortListener(hub, this, channel);
        listener.start();
    }

    /** Stops listening at once: a connect after this is refused. @return true when it was listening */
    boolean stopListening() {
        if (listener == null) {
            return false;
        }
        listener.close();
        listener = null;
        return true;
    }

    @Override
    public String toString() {
        return "WSS port " + number + " (" + key + ")";
    }
}
