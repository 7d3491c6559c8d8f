package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * A port on the WSS machine for one {@link PortKey}. Its number is chosen by the OS when it is
 * first allocated and kept until the hub forgets the port (wss.portMemory, a kick); it listens
 * or not as the hub decides.
 *
 * <p>A bound but unconnected socket, the placeholder, holds the number for the port's whole life,
 * listening or not, so that the OS gives it to nobody else (not to another WSS port, nor to a
 * link's outgoing socket) and the port can listen on it again. It is bound first (port 0: the OS
 * chooses) and closed only when the hub gives the number back ({@link #release}); both sockets
 * set SO_REUSEADDR, which lets the listener bind beside it (Linux refuses the other order, a
 * socket beside a listening one). So a listener may close whenever it likes (a drain closes its
 * own when it reaches the marker, without the hub's lock) and the number is never free meanwhile:
 * a bind(0) never picks a number a socket is bound to, nor does a connect's implicit bind. A
 * connect to a number held only by the placeholder is refused. All state is guarded by the
 * hub's lock.
 */
final class WssPort {

    final PortKey key;
    final int number;
    /** The connections accepted here that are still open. */
    private final Set<Link> links = new HashSet<>();
    private final Hub hub;
    private final InetAddress bindAddress;
    private PortListener listener;
    private SocketChannel placeholder;

    private WssPort(Hub hub, PortKey key, InetAddress bindAddress, int number) {
        this.hub = hub;
        this.key = key;
        this.bindAddress = bindAddress;
        this.number = number;
    }

    /** Binds a new OS-chosen port, listening on it or not. */
    static WssPort allocate(Hub hub, PortKey key, InetAddress bindAddress, boolean listen) throws IOException {
        SocketChannel placeholder = hold(new InetSocketAddress(bindAddress, 0));
        WssPort port = new WssPort(hub, key, bindAddress, placeholder.socket().getLocalPort());
        port.placeholder = placeholder;
        if (listen) {
            try {
                port.listen();
            } catch (IOException e) {
                port.release();
                throw e;
            }
        }
        return port;
    }

    /** A connection accepted here is forwarded now. */
    void addLink(Link link) {
        links.add(link);
    }

    void removeLink(Link link) {
        links.remove(link);
    }

    boolean hasLinks() {
        return !links.isEmpty();
    }

    /** The open connections, a copy (to close them after the lock, say). */
    List<Link> links() {
        return List.copyOf(links);
    }

    /** Whether a link through this port still open connects to its target from the WSS's {@code outgoingPort}. */
    boolean hasLinkFrom(int outgoingPort) {
        return links.stream().anyMatch(link -> link.outgoingPort() == outgoingPort && !link.isClosed());
    }

    boolean listening() {
        return listener != null;
    }

    /** Whether this listener is the one the port listens with now (not one stopped by a break since). */
    boolean listensWith(PortListener current) {
        return listener == current;
    }

    /** Listens again on the same number. */
    void listen() throws IOException {
        if (listener == null) {
            startListener(bindListening());
        }
    }

    /**
     * A server socket bound to this port's number, beside the placeholder: no lock needed, so a
     * registration binds its ports before it takes the hub's lock to {@link #adopt} them.
     */
    ServerSocketChannel bindListening() throws IOException {
        return PortListener.bind(new InetSocketAddress(bindAddress, number));
    }

    /** Listens with a socket from {@link #bindListening}; its thread is started by the caller, after the lock. */
    PortListener adopt(ServerSocketChannel channel) {
        listener = new PortListener(hub, this, channel);
        return listener;
    }

    private void startListener(ServerSocketChannel channel) {
        adopt(channel).start();
    }

    /** The listener now (to drain it after the lock, see {@link PortListener#beginDrain}), or null. */
    PortListener listener() {
        return listener;
    }

    /** Where the port is reached from this machine: the bind address, or loopback for the wildcard. */
    InetAddress reach() {
        return bindAddress.isAnyLocalAddress() ? InetAddress.getLoopbackAddress() : bindAddress;
    }

    /** Stops listening at once, so that a connect is refused; keeps the number. @return true when it was listening */
    boolean stopListening() {
        if (listener == null) {
            return false;
        }
        listener.close(); // the placeholder keeps the number
        listener = null;
        return true;
    }

    /** Stops listening and gives the number back to the OS. */
    void release() {
        if (listener != null) {
            listener.close();
            listener = null;
        }
        Closing.quietly(placeholder);
        placeholder = null;
    }

    private static SocketChannel hold(InetSocketAddress address) throws IOException {
        SocketChannel channel = SocketChannel.open();
        try {
            channel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            channel.bind(address);
            return channel;
        } catch (IOException e) {
            channel.close();
            throw e;
        }
    }

    @Override
    public String toString() {
        return "WSS port " + number + " (" + key + ")";
    }
}
