package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.CancelledKeyException;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.atomic.LongAdder;
import java.util.concurrent.locks.LockSupport;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.CloseReason;
import org.usarsim.wss.hub.core.Connection;
import org.usarsim.wss.hub.core.PairCondition;
import org.usarsim.wss.hub.core.PairStats;
import org.usarsim.wss.hub.core.PortKey;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.Airtime;
import org.usarsim.wss.shaping.ShapedFlow;

/**
 * One forwarded connection: the socket a source robot opened on a WSS port, and the socket the
 * WSS opens to the target robot. Its own thread connects to the target, then waits on a
 * Selector over both channels and copies chunks each way, unchanged and in order. End of stream
 * or a reset on either side stops reading and ends both streams once what was read is written
 * (see {@link #finish}); a side that cannot be written to any more closes both at once.
 */
public final class Link implements Runnable, Connection {

    private static final Logger LOG = Logger.getLogger(Link.class.getName());
    private static final int CONNECT_TIMEOUT_MS = 5000;
    /** How long a finished link waits for both sides to end their streams. */
    private static final long FINISH_NS = TimeUnit.SECONDS.toNanos(5);
    /** How many chunks one direction moves before the other gets a turn. */
    private static final int CHUNKS_PER_TURN = 16;

    private final WssPort port;
    private final PortKey key;
    private final SocketChannel source;
    private final SocketChannel target;
    private final InetSocketAddress targetAddress;
    private final int outgoingPort;
    private final int chunkSize;
    private final SocketBuffers buffers;
    private final WssEventListener events;
    private final Switchboard switchboard;
    private final Selector selector;
    private final AtomicBoolean closed = new AtomicBoolean();
    /** The pair's counters: this link adds its bytes and its opening, and says why it closed. */
    private final PairStats stats;
    /** With links shaped: how; null forwards as fast as the machine goes (wss.shaping = off). */
    private final Shaping shaping;
    /** Why the link closes: the first reason given wins. */
    private final AtomicReference<CloseReason> closeReason = new AtomicReference<>();
    /** Set once the connection to the target is made (what the window lists as established). */
    private volatile boolean established;

    /** Binds the outgoing socket at once, so that REVERSEDNS knows its port before the target can ask. */
    public Link(Switchboard switchboard, WssPort port, SocketChannel source, InetSocketAddress targetAddress, int chunkSize,
            SocketBuffers buffers, WssEventListener events, PairStats stats, Shaping shaping) throws IOException {
        this.switchboard = switchboard;
        this.shaping = shaping;
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
        if (closed.compareAndSet(false, true)) {
            Closing.quietly(source);
            Closing.quietly(target);
            selector.wakeup();
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
            established = true;
            this.established = true;
            stats.opened();
            switchboard.established(this);
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
            stats.closed(closeReason.get());
            Closing.quietly(selector);
            switchboard.linkEnded(this, established);
        }
    }

    private boolean connect() {
        try {
            target.socket().connect(targetAddress, CONNECT_TIMEOUT_MS);
        } catch (IOException e) {
            if (!closed.get()) {
                switchboard.warn(LOG, "unreachable targets", source.socket().getInetAddress(), this + ": the target at "
                        + targetAddress.getAddress().getHostAddress() + ":" + targetAddress.getPort() + " did not accept ("
                        + e.getMessage() + "); closing the source's connection", null);
            }
            return false;
        }
        return !closed.get();
    }

    private void forward() throws IOException {
        for (SocketChannel channel : new SocketChannel[] {source, target}) {
            buffers.apply(channel);
            channel.setOption(StandardSocketOptions.TCP_NODELAY, true);
            // A robot that vanishes (crash, network gone) never closes its end: keepalive finds it.
            switchboard.keepAlive().apply(channel);
            channel.configureBlocking(false);
        }
        Direction up = new Direction(source, target, key.from(), key.to());
        Direction down = new Direction(target, source, key.to(), key.from());
        SelectionKey sourceKey = source.register(selector, SelectionKey.OP_READ);
        SelectionKey targetKey = target.register(selector, SelectionKey.OP_READ);
        if (shaping != null) {
            forwardShaped(up, down, sourceKey, targetKey);
            return;
        }
        while (!closed.get()) {
            up.coalesce(false);
            down.coalesce(false);
            selector.select();
            boolean sourceReady = sourceKey.isValid() && selector.selectedKeys().contains(sourceKey);
            boolean targetReady = targetKey.isValid() && selector.selectedKeys().contains(targetKey);
            int sourceOps = sourceReady ? sourceKey.readyOps() : 0;
            int targetOps = targetReady ? targetKey.readyOps() : 0;
            selector.selectedKeys().clear();
            if (closed.get()) {
                return;
            }
            if ((targetOps & SelectionKey.OP_WRITE) != 0) {
                up.flush();
            }
            if ((sourceOps & SelectionKey.OP_WRITE) != 0) {
                down.flush();
            }
            boolean ended = up.ended || down.ended;
            if (!ended && (sourceOps & SelectionKey.OP_READ) != 0) {
                up.move();
            }
            if (!ended && (targetOps & SelectionKey.OP_READ) != 0) {
                down.move();
            }
            ended = up.ended || down.ended;
            if (ended && !up.pending() && !down.pending()) {
                finish(up, down, sourceKey, targetKey);
                return;
            }
            sourceKey.interestOps(interest(ended, up, down));
            targetKey.interestOps(interest(ended, down, up));
        }
    }

    /**
     * The shaped loop (wss.shaping = on): each direction reads only what its {@link ShapedFlow}
     * has room for, and writes its bytes when they are due (their airtime's end plus the delay),
     * waiting on the selector at most until the next is due. The pair's condition is read at every
     * turn, so a rate change reaches the bytes still waiting within one poll of the hub's. As
     * unshaped, a side's end stops the reading, and both streams end once what was read is written.
     */
    private void forwardShaped(Direction up, Direction down, SelectionKey sourceKey, SelectionKey targetKey) throws IOException {
        long now = shaping.clock().getAsLong();
        up.shape(shaping.airtime(), shaping.up(), now);
        down.shape(shaping.airtime(), shaping.down(), now);
        try {
            while (!closed.get()) {
                now = shaping.clock().getAsLong();
                up.follow();
                down.follow();
                up.writeDue(now);
                down.writeDue(now);
                boolean ended = up.ended || down.ended;
                if (ended && up.flow.held() == 0 && down.flow.held() == 0) {
                    finish(up, down, sourceKey, targetKey);
                    return;
                }
                sourceKey.interestOps(shapedInterest(ended, up, down, now));
                targetKey.interestOps(shapedInterest(ended, down, up, now));
                waitAtMost(Math.min(up.flow.nanosUntilNext(now), down.flow.nanosUntilNext(now)));
                boolean sourceReadable = sourceKey.isValid() && selector.selectedKeys().contains(sourceKey) && sourceKey.isReadable();
                boolean targetReadable = targetKey.isValid() && selector.selectedKeys().contains(targetKey) && targetKey.isReadable();
                selector.selectedKeys().clear();
                if (closed.get()) {
                    return;
                }
                if (sourceReadable && !up.ended && !down.ended) {
                    up.readShaped(shaping.clock().getAsLong());
                }
                if (targetReadable && !up.ended && !down.ended) {
                    down.readShaped(shaping.clock().getAsLong());
                }
            }
        } finally {
            up.flow.close();
            down.flow.close();
        }
    }

    /**
     * Waits for the sockets, at most until something falls due: whole milliseconds on the
     * selector (rounded down, so it wakes no later than due), and the last fraction of a
     * millisecond parked, which the selector cannot wait for; rounding up instead made every hop
     * up to a millisecond late.
     */
    private void waitAtMost(long nanos) throws IOException {
        if (nanos == 0) {
            selector.selectNow();
        } else if (nanos == Long.MAX_VALUE) {
            selector.select();
        } else if (nanos >= 1_000_000) {
            selector.select(TimeUnit.NANOSECONDS.toMillis(nanos));
        } else {
            LockSupport.parkNanos(nanos);
            selector.selectNow();
        }
    }

    /** A channel is read while its direction has room, and written while bytes due for it wait. */
    private static int shapedInterest(boolean ended, Direction from, Direction to, long now) {
        int ops = !ended && from.flow.room() > 0 ? SelectionKey.OP_READ : 0;
        return to.flow.due(now) > 0 ? ops | SelectionKey.OP_WRITE : ops;
    }

    /**
     * Ends both streams without a reset once everything read is written: shuts down both outputs
     * (the end of stream follows what is queued), then reads and drops what either side still
     * sends until both have ended or {@link #FINISH_NS} has passed. Closing a socket with unread
     * input would reset the connection, and a reset throws away what is still queued for that side.
     */
    private void finish(Direction up, Direction down, SelectionKey sourceKey, SelectionKey targetKey) throws IOException {
        up.coalesce(false);
        down.coalesce(false);
        shutdownOutput(source);
        shutdownOutput(target);
        sourceKey.interestOps(up.ended ? 0 : SelectionKey.OP_READ);
        targetKey.interestOps(down.ended ? 0 : SelectionKey.OP_READ);
        long deadline = System.nanoTime() + FINISH_NS;
        while (!(up.ended && down.ended) && !closed.get()) {
            long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
            if (left <= 0) {
                LOG.fine(() -> this + ": a side did not end its stream in time; closing");
                return;
            }
            selector.select(left);
            selector.selectedKeys().clear();
            if (!up.ended && up.drop()) {
                sourceKey.interestOps(0);
            }
            if (!down.ended && down.drop()) {
                targetKey.interestOps(0);
            }
        }
    }

    /** Sends the end of stream after what is queued; a side that reset has no stream left to end. */
    private static void shutdownOutput(SocketChannel channel) {
        try {
            channel.shutdownOutput();
        } catch (IOException e) {
            // Reset or already closed: nothing to end.
        }
    }

    /** A channel is read while nothing it sent waits to be written, and written while something waits for it. */
    private static int interest(boolean ended, Direction from, Direction to) {
        int ops = !ended && !from.pending() ? SelectionKey.OP_READ : 0;
        return to.pending() ? ops | SelectionKey.OP_WRITE : ops;
    }

    /** One way of the link: reads from one channel, writes everything read to the other. */
    private final class Direction {
        private final SocketChannel in;
        private final SocketChannel out;
        private final String fromRobot;
        private final String toRobot;
        private final ByteBuffer buffer = ByteBuffer.allocateDirect(chunkSize);
        /** The pair's count of bytes written this way: one add per write, no lock. */
        private final LongAdder forwarded;
        /** The buffer holds read bytes not yet written. */
        private boolean pending;
        /** Nagle's algorithm is on for the output (see {@link #coalesce}). */
        private boolean coalescing;
        boolean ended;

        Direction(SocketChannel in, SocketChannel out, String fromRobot, String toRobot) {
            this.in = in;
            this.out = out;
            this.fromRobot = fromRobot;
            this.toRobot = toRobot;
            this.forwarded = stats.bytesFrom(fromRobot);
        }

        /** With shaping on: this direction's flow and its pair's live condition one way. */
        private ShapedFlow flow;
        private AtomicReference<PairCondition> condition;
        private PairCondition followed;

        void shape(Airtime airtime, AtomicReference<PairCondition> condition, long now) {
            this.condition = condition;
            this.followed = condition.get();
            flow = new ShapedFlow(airtime.open(fromRobot, toRobot, now), followed.bitsPerSecond(), followed.delayMs(), chunkSize);
        }

        /** Takes the pair's condition now: a new rate or delay applies to the bytes not yet on the air. */
        void follow() {
            PairCondition now = condition.get();
            if (now != followed) {
                followed = now;
                if (now.shaped()) {
                    flow.setConditions(now.bitsPerSecond(), now.delayMs());
                }
            }
        }

        /** Reads what the flow has room for, a chunk at a time, while each read fills what it asked. */
        void readShaped(long now) {
            for (int i = 0; i < CHUNKS_PER_TURN; i++) {
                int room = flow.room();
                if (room == 0) {
                    return;
                }
                buffer.clear();
                buffer.limit(Math.min(room, buffer.capacity()));
                int asked = buffer.limit();
                int read = read();
                if (read < 0) {
                    ended = true;
                    return;
                }
                if (read == 0) {
                    return;
                }
                buffer.flip();
                flow.accept(buffer, now);
                if (read < asked) {
                    return;
                }
            }
        }

        /** Writes what is due: the one count of bytes sent, as unshaped. */
        void writeDue(long now) throws IOException {
            int written = flow.writeTo(out, now);
            if (written > 0) {
                forwarded.add(written);
                events.dataSent(fromRobot, toRobot, written);
            }
        }

        boolean pending() {
            return pending;
        }

        /**
         * Reads and writes chunks while each read fills a whole chunk (more is probably right
         * behind it), until the output is full or the turn is over. A shorter read means the
         * input is drained for now, so the link goes back to waiting without asking again.
         */
        void move() throws IOException {
            for (int i = 0; i < CHUNKS_PER_TURN && !pending; i++) {
                int read = read();
                if (read < 0) {
                    ended = true;
                    return;
                }
                if (read == 0) {
                    return;
                }
                boolean full = read == buffer.capacity();
                coalesce(full);
                buffer.flip();
                pending = true;
                flush();
                if (!full) {
                    return;
                }
            }
        }

        /**
         * While a burst of full chunks passes, lets the OS hold the last partial segment of one
         * chunk until the next chunk fills it (Nagle's algorithm), instead of sending a tiny
         * segment per chunk. Off again for any shorter read and before the link waits: turning
         * TCP_NODELAY back on sends what is held at once, so no message waits for an ACK.
         */
        void coalesce(boolean on) throws IOException {
            if (on != coalescing) {
                out.setOption(StandardSocketOptions.TCP_NODELAY, !on);
                coalescing = on;
            }
        }

        /** Reads and drops what is there, once the other side has gone; @return true at end of stream. */
        boolean drop() throws IOException {
            int read = 0;
            for (int i = 0; i < CHUNKS_PER_TURN; i++) {
                buffer.clear();
                read = read();
                if (read <= 0) {
                    break;
                }
            }
            ended = read < 0;
            return ended;
        }

        /**
         * Reads into the buffer: -1 at end of stream, and also when the side reset the connection
         * or failed, since it is gone either way and what was read from it is still delivered.
         */
        private int read() {
            try {
                return in.read(buffer);
            } catch (IOException e) {
                if (!closed.get()) {
                    LOG.fine(() -> Link.this + ": " + fromRobot + "'s side failed: " + e);
                }
                return -1;
            }
        }

        /** Writes what waits; the buffer is cleared once all of it is out. */
        void flush() throws IOException {
            if (!pending) {
                return;
            }
            int written = out.write(buffer);
            if (written > 0) {
                // The one count of bytes sent: what reached the target's socket, for the statistics and the event log alike.
                forwarded.add(written);
                events.dataSent(fromRobot, toRobot, written);
            }
            if (!buffer.hasRemaining()) {
                buffer.clear();
                pending = false;
            }
        }
    }

    @Override
    public String toString() {
        return "link " + key + " (outgoing port " + outgoingPort + ")";
    }
}
