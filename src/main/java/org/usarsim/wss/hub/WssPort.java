package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.util.HashSet;
import java.util.Set;

/**
 * A port on the WSS machine for one {@link PortKey}. Its number is chosen by the OS when it is
 * first allocated and kept for the server's life; it listens or not as the hub decides.
 * All state is guarded by the hub's lock.
 */
final class WssPort {

    private static final int BACKLOG = 128;

    final PortKey key;
    final int number;
    /** The connections accepted here that are still open. */
    final Set<Link> links = new HashSet<>();
    private ServerSocketChannel channel;

    private WssPort(PortKey key, ServerSocketChannel channel) {
        this.key = key;
        this.channel = channel;
        this.number = channel.socket().getLocalPort();
    }

    /** Binds a new OS-chosen port, listening. */
    static WssPort allocate(PortKey key, InetAddress bindAddress) throws IOException {
        return new WssPort(key, open(new InetSocketAddress(bindAddress, 0)));
    }

    private static ServerSocketChannel open(InetSocketAddress address) throws IOException {
        ServerSocketChannel channel = ServerSocketChannel.open();
        try {
            channel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            channel.bind(address, BACKLOG);
            channel.configureBlocking(false);
            return channel;
        } catch (IOException e) {
            channel.close();
            throw e;
        }
    }

    boolean listening() {
        return channel != null;
    }

    /** The listening channel, or null. */
    ServerSocketChannel channel() {
        return channel;
    }

    /** Listens again on the same number. */
    void listen(InetAddress bindAddress) throws IOException {
        if (channel == null) {
            channel = open(new InetSocketAddress(bindAddress, number));
        }
    }

    /** @return true when it was listening */
    boolean stopListening() {
        if (channel == null) {
            return false;
        }
        Closing.quietly(channel);
        channel = null;
        return true;
    }

    @Override
    public String toString() {
        return "WSS port " + number + " (" + key + ")";
    }
}
