package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketOption;
import java.net.StandardSocketOptions;
import java.nio.channels.NetworkChannel;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.WssPort;

/**
 * The socket of one WSS port: what the core's {@link WssPort} is on the machine. Its number is
 * chosen by the OS when a DNS first binds it ({@link #bind}; a fixed port's is configured) and
 * kept until the hub forgets the port (wss.portMemory, a kick, descriptors running short); it
 * listens or not as the hub applies the core's decisions, one descriptor either way:
 * <ul>
 * <li>listening, its listening socket ({@link PortListener}, on the {@link PortSelector}) holds
 * the number;</li>
 * <li>not listening, a bound, unconnected socket (the placeholder) holds it; a connect to the
 * number is refused.</li>
 * </ul>
 * To stop, the placeholder is bound beside the listening socket, then the listener closed; to
 * listen again, a listener is bound beside the placeholder, then the placeholder closed. So the
 * number is never free meanwhile (two descriptors for that moment). Both set SO_REUSEPORT and
 * not SO_REUSEADDR: Linux lets two sockets share a number, one of them listening, only when both
 * set SO_REUSEPORT and belong to the same user; a socket that does not set it cannot bind the
 * number, a bind(0) and a connect's implicit bind never pick a number a socket is bound to
 * (docs/reliability.md, "Port numbers held").
 *
 * <p>Its methods are called by the hub in the order of the core's decisions (a departure's drain
 * and the giving back of ports when descriptors run short may come between): each is
 * synchronized, and once the port is released nothing more is done. None of them calls the hub,
 * and none waits for anything but the selector's thread.
 */
public final class PortSockets {

    private static final Logger LOG = Logger.getLogger(PortSockets.class.getName());
    /** Connections the OS completes before the selector accepts them: each port is for one source robot. */
    private static final int BACKLOG = 128;
    /** What lets the listener and the placeholder share the number (SO_REUSEADDR where the OS has no SO_REUSEPORT). */
    private static final SocketOption<Boolean> SHARE = sharing();

    private final WssPort port;
    private final InetSocketAddress address;
    private final PortSelector selector;
    /** Listening now, or the last listener (closing or closed); null when it never listened. */
    private PortListener listener;
    /** The socket a DNS bound with the number, for the first {@link #listen}; null once used. */
    private ServerSocketChannel fresh;
    /** Holds the number while the port does not listen; null while it listens. */
    private SocketChannel placeholder;
    private boolean released;

    private PortSockets(WssPort port, InetAddress bindAddress, PortSelector selector, ServerSocketChannel fresh) {
        this.port = port;
        this.address = new InetSocketAddress(bindAddress, port.number);
        this.selector = selector;
        this.fresh = fresh;
    }

    private static SocketOption<Boolean> sharing() {
        try (ServerSocketChannel probe = ServerSocketChannel.open()) {
            return probe.supportedOptions().contains(StandardSocketOptions.SO_REUSEPORT) ? StandardSocketOptions.SO_REUSEPORT
                    : StandardSocketOptions.SO_REUSEADDR;
        } catch (IOException e) {
            return StandardSocketOptions.SO_REUSEPORT;
        }
    }

    /**
     * A new listening socket for a port about to be opened, bound before the port is allocated: on
     * a number the OS chooses (0: a DNS's), or on a fixed port's number (docs/fixed-ports.md).
     */
    public static ServerSocketChannel bind(InetAddress bindAddress, int number) throws IOException {
        return bindListening(new InetSocketAddress(bindAddress, number));
    }

    /** The number a socket from {@link #bind} holds. */
    public static int numberOf(ServerSocketChannel bound) {
        return bound.socket().getLocalPort();
    }

    /**
     * The socket of a port the core allocated with the number of {@code fresh} (from
     * {@link #bind}), which the port's first {@link #listen} takes; a port allocated not
     * listening is {@link #stop}ped in the same step, and keeps its number with a placeholder.
     */
    public static PortSockets adopt(WssPort port, InetAddress bindAddress, PortSelector selector, ServerSocketChannel fresh) {
        return new PortSockets(port, bindAddress, selector, fresh);
    }

    /**
     * Listens on the port's number, with a listener of the core's {@code epoch}. A listener
     * closed before must be closed for real first: two listening sockets on one number would share
     * its connections. A new port's first listening only joins the selector (the hub does it under
     * its lock; {@code closes} may then be null).
     *
     * @throws IOException when the number cannot be listened on (no descriptor left, say: the hub
     *                     may give some back and try once more)
     */
    public synchronized void listen(int epoch, Closes closes) throws IOException {
        if (released) {
            return;
        }
        if (listener != null && !listener.isClosed()) {
            stop(closes);
            closes.await();
            listener.awaitClosed(selector.clock().nanoTime() + PortSelector.CLOSE_WAIT_NS);
        }
        ServerSocketChannel channel = fresh != null ? fresh : bindListening(address);
        fresh = null;
        PortListener started = new PortListener(port, epoch, channel, selector.clock());
        try {
            selector.register(started);
        } catch (IOException e) {
            Closing.quietly(channel);
            throw e;
        }
        listener = started;
        Closing.quietly(placeholder); // the listener holds the number now
        placeholder = null;
    }

    /** Stops listening: once {@code closes} is awaited a connect is refused. Keeps the number. */
    public synchronized void stop(Closes closes) {
        if (released) {
            return;
        }
        if (fresh != null) {
            ServerSocketChannel unused = fresh;
            fresh = null;
            holdInstead(unused, closes); // never registered: closed at once
        }
        if (listener != null && !listener.isClosed()) {
            closes.add(listener);
            if (placeholder == null) {
                holdInstead(null, closes);
            }
        }
    }

    /** Stops listening and gives the number back to the OS (once {@code closes} is awaited). */
    public synchronized void release(Closes closes) {
        if (released) {
            return;
        }
        released = true;
        Closing.quietly(fresh);
        fresh = null;
        if (listener != null && !listener.isClosed()) {
            closes.add(listener);
        }
        Closing.quietly(placeholder);
        placeholder = null;
    }

    /**
     * Begins a departure's drain: the connections the kernel already completed are handed over,
     * then the listener accepts no more ({@link PortListener#beginDrain}); it keeps the number
     * until the departure stops the port, at once ({@link #stop}, before the robot is gone).
     *
     * @return the listener draining, to wait for; null when there is none (the stop closes it)
     */
    public synchronized PortListener beginDrain() {
        if (released || listener == null || listener.isClosing()) {
            return null;
        }
        InetAddress reach = address.getAddress().isAnyLocalAddress() ? InetAddress.getLoopbackAddress() : address.getAddress();
        return listener.beginDrain(reach) ? listener : null;
    }

    /**
     * Binds the placeholder beside the socket that listens ({@code unregistered}, or the listener
     * in {@code closes}), then lets that one go. Without a descriptor for it, the listening socket
     * is closed first and the placeholder bound on the number it freed: the port must stop (a
     * break refuses connections), and for that instant the number is not held.
     */
    private void holdInstead(ServerSocketChannel unregistered, Closes closes) {
        try {
            placeholder = bindPlaceholder(address);
            Closing.quietly(unregistered);
            return;
        } catch (IOException e) {
            Closing.quietly(unregistered);
            closes.await();
        }
        try {
            placeholder = bindPlaceholder(address);
        } catch (IOException e) {
            LOG.warning(port + ": cannot hold its number while it does not listen (" + e.getMessage()
                    + "); it stops all the same, and listens again on the number if it is still free");
        }
    }

    private static ServerSocketChannel bindListening(InetSocketAddress address) throws IOException {
        ServerSocketChannel channel = ServerSocketChannel.open();
        try {
            share(channel);
            channel.bind(address, BACKLOG);
            channel.configureBlocking(false); // for the selector: here, not under the hub's lock, where a DNS's port joins it
            return channel;
        } catch (IOException | RuntimeException e) {
            channel.close();
            throw e;
        }
    }

    private static SocketChannel bindPlaceholder(InetSocketAddress address) throws IOException {
        SocketChannel channel = SocketChannel.open();
        try {
            share(channel);
            channel.bind(address);
            return channel;
        } catch (IOException | RuntimeException e) {
            channel.close();
            throw e;
        }
    }

    /**
     * SO_REUSEPORT on, SO_REUSEADDR off (the JDK sets it on a ServerSocketChannel by default): with
     * it, a socket of any process that sets SO_REUSEADDR could bind the number while only the
     * placeholder holds it, and Linux's bind(0) searches for a free number 17 times slower (2.3 s
     * against 0.13 s for 10,000 listening sockets here).
     */
    private static void share(NetworkChannel channel) throws IOException {
        if (SHARE != StandardSocketOptions.SO_REUSEADDR) {
            channel.setOption(StandardSocketOptions.SO_REUSEADDR, false);
        }
        channel.setOption(SHARE, true);
    }

    @Override
    public String toString() {
        return port.toString();
    }
}
