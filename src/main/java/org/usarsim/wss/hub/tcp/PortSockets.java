package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import org.usarsim.wss.hub.core.WssPort;

/**
 * The sockets of one WSS port: what the core's {@link WssPort} is on the machine. Its number is
 * chosen by the OS when the port is first allocated ({@link #hold}) and kept until the hub forgets
 * the port (wss.portMemory, a kick); it listens or not as the hub applies the core's decisions.
 *
 * <p>A bound but unconnected socket, the placeholder, holds the number for the port's whole life,
 * listening or not, so that the OS gives it to nobody else (not to another WSS port, nor to a
 * link's outgoing socket) and the port can listen on it again. It is bound first (port 0: the OS
 * chooses) and closed only when the hub gives the number back ({@link #release}); both sockets
 * set SO_REUSEADDR, which lets the listener bind beside it (Linux refuses the other order, a
 * socket beside a listening one). So a listener may close whenever it likes (a drain closes its
 * own when it reaches the marker, without the hub's lock) and the number is never free meanwhile:
 * a bind(0) never picks a number a socket is bound to, nor does a connect's implicit bind. A
 * connect to a number held only by the placeholder is refused. Its methods are called by the
 * hub in the order of the core's decisions, one thread at a time.
 */
public final class PortSockets {

    private final WssPort port;
    private final InetAddress bindAddress;
    private final SocketChannel placeholder;
    /** The listener now, or null. Read by a departure's drain too. */
    private volatile PortListener listener;
    /** A listening socket bound with the number, for the first {@link #listen}; null once used or when there is none. */
    private ServerSocketChannel bound;

    private PortSockets(WssPort port, InetAddress bindAddress, SocketChannel placeholder, ServerSocketChannel bound) {
        this.port = port;
        this.bindAddress = bindAddress;
        this.placeholder = placeholder;
        this.bound = bound;
    }

    /** Binds a new OS-chosen number and holds it; {@link #adopt} then gives it its core port. */
    public static SocketChannel hold(InetAddress bindAddress) throws IOException {
        SocketChannel channel = SocketChannel.open();
        try {
            channel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            channel.bind(new InetSocketAddress(bindAddress, 0));
            return channel;
        } catch (IOException e) {
            channel.close();
            throw e;
        }
    }

    /** The number a placeholder from {@link #hold} holds. */
    public static int numberOf(SocketChannel placeholder) {
        return placeholder.socket().getLocalPort();
    }

    /**
     * A listening socket on a held number, bound beside its placeholder: a DNS binds it with the
     * number, so that a port that cannot listen (out of descriptors, say) is never allocated.
     */
    public static ServerSocketChannel bindListening(InetAddress bindAddress, int number) throws IOException {
        return PortListener.bind(new InetSocketAddress(bindAddress, number));
    }

    /**
     * The sockets of a port the core allocated with the placeholder's number, and the listening
     * socket bound with it, which the port's first {@link #listen} uses (closed at once when the
     * port does not listen).
     */
    public static PortSockets adopt(WssPort port, InetAddress bindAddress, SocketChannel placeholder, ServerSocketChannel bound) {
        if (!port.listening()) {
            Closing.quietly(bound);
            bound = null;
        }
        return new PortSockets(port, bindAddress, placeholder, bound);
    }

    /**
     * Listens on the port's number again, with a listener of the core's {@code epoch}; its thread
     * hands connections to the switchboard.
     */
    public void listen(Switchboard switchboard, int epoch) throws IOException {
        stopListening();
        ServerSocketChannel channel = bound != null ? bound : bindListening(bindAddress, port.number);
        bound = null;
        PortListener started = new PortListener(switchboard, port, epoch, channel);
        listener = started;
        started.start();
    }

    /** Stops listening at once, so that a connect is refused; keeps the number. */
    public void stopListening() {
        PortListener current = listener;
        if (current != null) {
            listener = null;
            current.close(); // the placeholder keeps the number
        }
    }

    /** Stops listening and gives the number back to the OS. */
    public void release() {
        stopListening();
        Closing.quietly(bound);
        Closing.quietly(placeholder);
    }

    /**
     * Begins a departure's drain: the connections the kernel already completed are handed over,
     * then the listener stops ({@link PortListener#beginDrain}).
     *
     * @return the listener draining, to wait for; null when there is none
     */
    public PortListener beginDrain() {
        PortListener current = listener;
        InetAddress reach = bindAddress.isAnyLocalAddress() ? InetAddress.getLoopbackAddress() : bindAddress;
        return current != null && current.beginDrain(reach) ? current : null;
    }

    @Override
    public String toString() {
        return port.toString();
    }
}
