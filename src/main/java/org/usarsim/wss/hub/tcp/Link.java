package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.CancelledKeyException;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.CloseReason;
import org.usarsim.wss.hub.core.Connection;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.hub.core.PairStats;
import org.usarsim.wss.hub.core.PortKey;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.Pacing;
import org.usarsim.wss.shaping.Unpaced;

/**
 * One forwarded connection: the socket a source robot opened on a WSS port, and the socket the
 * WSS opens to the target robot. Its own thread connects to the target, then runs the
 * forwarding loop ({@link Forwarding}: each direction {@link Unpaced}, or {@link LiveShaping} with
 * links shaped) until the link closes, and tells the hub it ended. End of stream or a reset on either side
 * stops reading and ends both streams once what was read is written ({@link Forwarding#finish});
 * a side that cannot be written to any more closes both at once.
 */
public final class Link implements Runnable, Connection {

    private static final Logger LOG = Logger.getLogger(Link.class.getName());
    private static final int CONNECT_TIMEOUT_MS = 5000;

    private final WssPort port;
    private final PortKey key;
    private final SocketChannel source;
    private final SocketChannel target;
    private final InetSocketAddress targetAddress;
    private final int outgoingPort;
    private final int chunkSize;
    private final SocketBuffers buffers;
    private final WssEventListener events;
    private final LinkHub hub;
    private final Selector selector;
    private final AtomicBoolean closed = new AtomicBoolean();
    /** Held while a direction writes and reports what it wrote, and by {@link #close}: no byte is sent once closed. */
    final Object sending = new Object();
    /** The pair's counters: this link adds its bytes and its opening, and says why it closed. */
    private final PairStats stats;
    /** With links shaped: how; null forwards as fast as the machine goes (wss.shaping = off). */
    private final Shaping shaping;
    /** The hub's clock: the shaped directions' time, and the wait for both streams' ends. */
    private final HubClock clock;
    /** Why the link closes: the first reason given wins. */
    private final AtomicReference<CloseReason> closeReason = new AtomicReference<>();
    /** Set once the connection to the target is made (what the window lists as established). */
    private volatile boolean established;

    /** Binds the outgoing socket at once, so that REVERSEDNS knows its port before the target can ask. */
    public Link(LinkHub hub, WssPort port, SocketChannel source, InetSocketAddress targetAddress, int chunkSize,
            SocketBuffers buffers, WssEventListener events, PairStats stats, HubClock clock, Shaping shaping) throws IOException {
        this.hub = hub;
        this.shaping = shaping;
        this.clock = clock;
        this.stats = stats;
        this.port = port;
        this.key = port.key;
        this.source = source;
        this.targetAddress = targetAddress;
        this.chunkSize = chunkSize;
        this.buffers = buffers;
        this.events = events;
        SocketChannel outgoing = SocketChannel.open();
        Selector opened = null;
        try {
            outgoing.bind(new InetSocketAddress(0));
            opened = Selector.open();
        } catch (IOException e) {
            Closing.quietly(outgoing);
            throw e;
        }
        this.target = outgoing;
        this.selector = opened;
        this.outgoingPort = ((InetSocketAddress) outgoing.getLocalAddress()).getPort();
    }

    /** The port the link was accepted on. */
    public WssPort port() {
        return port;
    }

    @Override
    public boolean isEstablished() {
        return established;
    }

    /** Both legs' sockets (for the tests of their options). */
    public List<SocketChannel> channels() {
        return List.of(source, target);
    }

    @Override
    public boolean isClosed() {
        return closed.get();
    }

    /** The local port of the WSS's socket to the target: what the target sees as its peer's port. */
    @Override
    public int outgoingPort() {
        return outgoingPort;
    }

    public void start() {
        Thread thread = new Thread(this, "link " + key);
        thread.setDaemon(true);
        thread.start();
    }

    /** Closes both ends now; the link's thread ends and tells the hub. Safe from any thread, more than once. */
    void close() {
        close(CloseReason.PEER_CLOSED);
    }

    /** As {@link #close()}, saying why (the pair's last close, unless another reason came first). */
    @Override
    public void close(CloseReason reason) {
        closeReason.compareAndSet(null, reason);
        synchronized (sending) { // a write under way is written and reported first; none after
            if (closed.compareAndSet(false, true)) {
                // The pair's last close as the link closes: a snapshot that no longer lists the link already says why.
                stats.closed(closeReason.get());
                if (CUTS.contains(reason)) {
                    resetOnClose(source);
                    resetOnClose(target);
                }
                Closing.quietly(source);
                Closing.quietly(target);
                selector.wakeup();
            }
        }
    }

    /**
     * The closes that cut a stream (a break, a kick, a FORCE down, the server's stop): both ends get
     * a reset, not an end of stream, so that neither robot takes a cut stream for a finished one
     * (issue 27; docs/protocol.md section 4.3). An end's own close or reset ends the link cleanly.
     */
    private static final Set<CloseReason> CUTS = EnumSet.of(CloseReason.OUT_OF_RANGE, CloseReason.KICKED, CloseReason.FORCED,
            CloseReason.SERVER_STOPPED);

    /** SO_LINGER 0: the close sends a reset (RST) instead of an end of stream (FIN). */
    private static void resetOnClose(SocketChannel channel) {
        try {
            channel.setOption(StandardSocketOptions.SO_LINGER, 0);
        } catch (IOException | RuntimeException e) {
            // Not connected or already closed: nothing to reset.
        }
    }

    /** For a link whose thread never started: closes everything it holds. */
    public void discard() {
        close();
        Closing.quietly(selector);
    }

    @Override
    public void run() {
        boolean established = false;
        try {
            if (!connect()) {
                closeReason.compareAndSet(null, CloseReason.TARGET_REFUSED);
                return;
            }
            if (!hub.established(this, this::opened)) { // closed by a step (a FORCE down, say) before it could be announced
                return;
            }
            established = true;
            forward();
        } catch (IOException | CancelledKeyException | ClosedSelectorException e) {
            // A reset or an error on a socket, or a close from another thread: the link is over.
            if (!closed.get()) {
                LOG.fine(() -> this + " ended: " + e);
            }
        } catch (RuntimeException | Error e) {
            LOG.log(Level.WARNING, this + " failed: " + e, e);
        } finally {
            close();
            Closing.quietly(selector);
            hub.linkEnded(this, established);
        }
    }

    /** Established: listed so, and counted, before the listeners hear of it. */
    private void opened() {
        established = true;
        stats.opened();
    }

    private boolean connect() {
        try {
            target.socket().connect(targetAddress, CONNECT_TIMEOUT_MS);
        } catch (IOException e) {
            if (!closed.get()) {
                hub.warn(LOG, "unreachable targets", source.socket().getInetAddress(), this + ": the target at "
                        + targetAddress.getAddress().getHostAddress() + ":" + targetAddress.getPort() + " did not accept ("
                        + e.getMessage() + "); closing the source's connection", null);
            }
            return false;
        }
        return !closed.get();
    }

    private void forward() throws IOException {
        for (SocketChannel channel : new SocketChannel[] {source, target}) {
            if (shaping == null) {
                buffers.apply(channel); // a shaped link sizes them by its rate before it reads (LiveShaping)
            }
            channel.setOption(StandardSocketOptions.TCP_NODELAY, true);
            // A robot that vanishes (crash, network gone) never closes its end: keepalive finds it.
            hub.keepAlive().apply(channel);
            channel.configureBlocking(false);
        }
        Runnable wake = selector::wakeup; // the one instance each shaped direction watches and unwatches
        long now = clock.nanoTime();
        Pacing upPacing = null;
        Pacing downPacing = null;
        try {
            upPacing = pacing(true, wake, now);
            downPacing = pacing(false, wake, now);
            Direction up = new Direction(this, source, target, key.from(), key.to(), chunkSize, stats, events, upPacing);
            Direction down = new Direction(this, target, source, key.to(), key.from(), chunkSize, stats, events, downPacing);
            new Forwarding(this, selector, clock, up, down).forward();
        } finally {
            closeIfMade(upPacing);
            closeIfMade(downPacing);
        }
    }

    /**
     * The pacing of the direction from the source to the target ({@code upward}) or back: at
     * once, or as the pair's live condition that way says.
     */
    private Pacing pacing(boolean upward, Runnable wake, long now) {
        if (shaping == null) {
            return new Unpaced();
        }
        return upward ? new LiveShaping(shaping, shaping.up(), source, target, key.from(), key.to(), wake, now)
                : new LiveShaping(shaping, shaping.down(), target, source, key.to(), key.from(), wake, now);
    }

    private static void closeIfMade(Pacing pacing) {
        if (pacing != null) {
            pacing.close();
        }
    }

    @Override
    public String toString() {
        return "link " + key + " (outgoing port " + outgoingPort + ")";
    }
}
