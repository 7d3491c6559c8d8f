package org.usarsim.wss.hub.udp;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.FixedPort;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.hub.core.LiveCondition;
import org.usarsim.wss.hub.core.PairCondition;
import org.usarsim.wss.hub.core.UdpCounts;
import org.usarsim.wss.shaping.Airtime;
import org.usarsim.wss.shaping.DatagramFlow;
import org.usarsim.wss.shaping.JitterConfig;

/**
 * A fixed UDP port (docs/fixed-ports.md): one datagram socket on its number, and a thread that
 * relays. A datagram from a sender goes to the target from the sender's session socket
 * ({@link UdpSessions}), the target's answers to that socket go back to the sender from the fixed
 * port. Each way reads the pair's condition live: broken, a datagram is dropped (counted); shaped,
 * it goes through its direction's {@link DatagramFlow} (queue, rate, delay, loss), whose datagrams
 * still queued take a new rate at once (a change wakes the thread: {@link LiveCondition}); unshaped, at once.
 */
public final class UdpRelay implements AutoCloseable {

    private static final Logger LOG = Logger.getLogger(UdpRelay.class.getName());
    /** Larger than any datagram, so that none is cut: a read of a larger one would truncate it. */
    private static final int BUFFER = 65_536;
    /** The socket buffers, so that a burst at full speed is not dropped by the kernel before the thread reads it. */
    private static final int SOCKET_BUFFER = 4 * 1024 * 1024;

    /** How often the counts are reported, when they changed. */
    private static final long REPORT_NS = 1_000_000_000L;

    /** Where the relay reports what its datagrams did, each way, at most once a second (the event log). */
    public interface Report {
        void counted(String from, String to, UdpCounts.Reading since);
    }

    /**
     * The pair's side of the relay: conditions and counters each way, from the hub's core. The
     * relay counts its own port's datagrams ({@link UdpCounts#of}), added to these: what it
     * reports is its port's alone, however many fixed UDP ports the pair has.
     */
    public record Pair(LiveCondition up, LiveCondition down, UdpCounts upCounts, UdpCounts downCounts) {
    }

    private final FixedPort port;
    private final InetSocketAddress target;
    private final InetAddress source;
    private final InetAddress bindAddress;
    private final Pair pair;
    /** This port's counts each way (each added to the pair's): what it reports. */
    private final UdpCounts upCounts;
    private final UdpCounts downCounts;
    private final HubClock clock;
    private final Selector selector;
    private final DatagramChannel front;
    private final UdpSessions<DatagramChannel> sessions;
    private final DatagramFlow<UdpSessions.Session<DatagramChannel>> forward;
    private final DatagramFlow<InetSocketAddress> back;
    private final ByteBuffer buffer = ByteBuffer.allocateDirect(BUFFER);
    private final Thread thread;
    private volatile boolean closed;
    private long lostForward;
    private long lostBack;
    private long refusedSenders;
    private final Report report;
    private UdpCounts.Reading reportedUp = UdpCounts.Reading.NONE;
    private UdpCounts.Reading reportedDown = UdpCounts.Reading.NONE;
    private long nextReportNs;

    /**
     * Binds the port's number; {@link #start} starts relaying.
     *
     * @param source the address the source robot's datagrams must come from; null: any
     * @param jitter the jitter's distribution, whether datagrams may be reordered, and the seed (the jitter itself is the pair's)
     * @throws IOException when the number cannot be bound
     */
    public UdpRelay(FixedPort port, InetAddress bindAddress, InetSocketAddress target, InetAddress source, Pair pair,
            Airtime airtime, JitterConfig jitter, long idleNs, HubClock clock, Report report) throws IOException {
        this.report = report;
        this.port = port;
        this.target = target;
        this.source = source;
        this.bindAddress = bindAddress;
        this.pair = pair;
        this.upCounts = UdpCounts.of(pair.upCounts());
        this.downCounts = UdpCounts.of(pair.downCounts());
        this.clock = clock;
        this.sessions = new UdpSessions<>(idleNs);
        long now = clock.nanoTime();
        long seed = port.number() * 2L;
        this.forward = new DatagramFlow<>(airtime.open(port.key().from(), port.key().to(), now), seed, jitter.distribution(), jitter.reorder(),
                jitter.seedFor(port.key().from(), port.key().to(), port.number()));
        this.back = new DatagramFlow<>(airtime.open(port.key().to(), port.key().from(), now), seed + 1, jitter.distribution(),
                jitter.reorder(), jitter.seedFor(port.key().to(), port.key().from(), port.number()));
        this.selector = Selector.open();
        DatagramChannel bound = null;
        try {
            bound = DatagramChannel.open();
            bound.setOption(StandardSocketOptions.SO_RCVBUF, SOCKET_BUFFER);
            bound.setOption(StandardSocketOptions.SO_SNDBUF, SOCKET_BUFFER);
            bound.bind(new InetSocketAddress(bindAddress, port.number()));
            bound.configureBlocking(false);
            bound.register(selector, SelectionKey.OP_READ);
        } catch (IOException | RuntimeException e) {
            if (bound != null) {
                bound.close();
            }
            selector.close();
            throw e;
        }
        this.front = bound;
        this.thread = new Thread(this::run, "wss-udp-" + port.number());
        thread.setDaemon(true);
    }

    public void start() {
        thread.start();
    }

    /** The number the port is bound to. */
    public int number() {
        return port.number();
    }

    public FixedPort port() {
        return port;
    }

    /** The senders that have a session now. */
    public int sessions() {
        synchronized (sessions) {
            return sessions.size();
        }
    }

    private void run() {
        Runnable wake = selector::wakeup;
        pair.up().watch(wake); // before the first reading of the conditions: no change is missed
        pair.down().watch(wake);
        try {
            while (!closed) {
                follow();
                long now = clock.nanoTime();
                long waitNs;
                synchronized (sessions) {
                    waitNs = Math.min(Math.min(forward.nanosUntilNext(now), back.nanosUntilNext(now)), sessions.nanosUntilExpiry(now));
                }
                waitNs = Math.min(waitNs, REPORT_NS);
                if (waitNs <= 0) {
                    selector.selectNow();
                } else if (waitNs == Long.MAX_VALUE) {
                    selector.select();
                } else {
                    selector.select(Math.max(1, (clock.waitNanos(waitNs) + 999_999) / 1_000_000));
                }
                for (SelectionKey key : selector.selectedKeys()) {
                    if (key.isValid() && key.isReadable()) {
                        readAll(key);
                    }
                }
                selector.selectedKeys().clear();
                sendDue(clock.nanoTime());
                if (clock.nanoTime() - nextReportNs >= 0) {
                    reportCounts();
                    nextReportNs = clock.nanoTime() + REPORT_NS;
                }
            }
        } catch (IOException | RuntimeException e) {
            if (!closed) {
                LOG.log(Level.WARNING, "fixed UDP port " + port.number() + " (" + port + ") stopped: " + e, e);
            }
        } finally {
            pair.up().unwatch(wake);
            pair.down().unwatch(wake);
            reportCounts();
            closeAll();
        }
    }

    /** A shaped pair's conditions now, for the datagrams each way still queues (and, the jitter, for those read next). */
    private void follow() {
        PairCondition up = pair.up().get();
        if (up.shaped()) {
            forward.setConditions(up.bitsPerSecond(), up.delayMs(), up.lossPercent());
            forward.setLossRule(lossRule(up));
            forward.setJitterMs(up.jitterMs());
        }
        PairCondition down = pair.down().get();
        if (down.shaped()) {
            back.setConditions(down.bitsPerSecond(), down.delayMs(), down.lossPercent());
            back.setLossRule(lossRule(down));
            back.setJitterMs(down.jitterMs());
        }
    }

    /** The model's rule for a datagram's loss (the RFComms model's), when it gives one; null: the loss percent. */
    private static DatagramFlow.LossRule lossRule(PairCondition condition) {
        return condition.datagramLoss() == null ? null : condition.datagramLoss()::lost;
    }

    /** The counts since the last report, each way that has any. */
    private void reportCounts() {
        UdpCounts.Reading up = upCounts.read();
        UdpCounts.Reading down = downCounts.read();
        UdpCounts.Reading upSince = since(up, reportedUp);
        UdpCounts.Reading downSince = since(down, reportedDown);
        reportedUp = up;
        reportedDown = down;
        try {
            if (!upSince.none()) {
                report.counted(port.key().from(), port.key().to(), upSince);
            }
            if (!downSince.none()) {
                report.counted(port.key().to(), port.key().from(), downSince);
            }
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, "fixed UDP port " + port.number() + ": reporting its counts failed: " + e, e);
        }
    }

    private static UdpCounts.Reading since(UdpCounts.Reading now, UdpCounts.Reading before) {
        return new UdpCounts.Reading(now.datagrams() - before.datagrams(), now.bytes() - before.bytes(),
                now.droppedBroken() - before.droppedBroken(), now.droppedQueue() - before.droppedQueue(), now.lost() - before.lost());
    }

    @SuppressWarnings("unchecked")
    private void readAll(SelectionKey key) throws IOException {
        DatagramChannel channel = (DatagramChannel) key.channel();
        while (true) {
            buffer.clear();
            SocketAddress from;
            try {
                from = channel.receive(buffer);
            } catch (IOException e) { // the target's port unreachable, say: what was sent is lost, as UDP's is
                return;
            }
            if (from == null) {
                return;
            }
            buffer.flip();
            byte[] data = new byte[buffer.remaining()];
            buffer.get(data);
            long now = clock.nanoTime();
            if (channel == front) {
                fromSender((InetSocketAddress) from, data, now);
            } else {
                fromTarget((UdpSessions.Session<DatagramChannel>) key.attachment(), data, now);
            }
        }
    }

    private void fromSender(InetSocketAddress sender, byte[] data, long now) {
        if (source != null && !source.equals(sender.getAddress())) {
            if (refusedSenders++ % 1000 == 0) {
                LOG.warning("fixed UDP port " + port.number() + " (" + port + "): dropped a datagram from "
                        + sender.getAddress().getHostAddress() + ", not " + port.key().from() + "'s address " + source.getHostAddress());
            }
            return;
        }
        PairCondition condition = pair.up().get();
        if (!condition.passes()) {
            upCounts.droppedBroken();
            return;
        }
        UdpSessions.Session<DatagramChannel> session;
        synchronized (sessions) {
            session = sessions.from(sender, now);
            if (session == null) {
                DatagramChannel socket = null;
                try {
                    socket = DatagramChannel.open();
                    socket.setOption(StandardSocketOptions.SO_RCVBUF, SOCKET_BUFFER);
                    socket.setOption(StandardSocketOptions.SO_SNDBUF, SOCKET_BUFFER);
                    socket.bind(new InetSocketAddress(bindAddress, 0));
                    socket.connect(target);
                    socket.configureBlocking(false);
                    socket.register(selector, SelectionKey.OP_READ);
                } catch (IOException e) { // no descriptor left, say: this datagram is lost, the port goes on
                    if (socket != null) {
                        closeQuietly(socket);
                    }
                    LOG.warning("fixed UDP port " + port.number() + " (" + port + "): no socket toward " + target + " for "
                            + sender + ": " + e);
                    return;
                }
                session = sessions.open(sender, socket, now);
                socket.keyFor(selector).attach(session);
            }
        }
        if (!condition.shaped() && forward.idle()) { // unshaped: sent at once, not held
            sendToTarget(session, data);
            return;
        }
        forward.setConditions(condition.bitsPerSecond(), condition.delayMs(), condition.lossPercent());
        forward.setLossRule(lossRule(condition));
        if (!forward.offer(data, session, now)) {
            upCounts.droppedQueue();
        }
    }

    private void sendToTarget(UdpSessions.Session<DatagramChannel> session, byte[] data) {
        try {
            session.socket().write(ByteBuffer.wrap(data));
            upCounts.sent(data.length);
        } catch (IOException e) { // the target refuses (its port unreachable): lost, as UDP's is
            LOG.fine("fixed UDP port " + port.number() + ": not sent to " + target + ": " + e);
        }
    }

    private void sendToSender(InetSocketAddress sender, byte[] data) throws IOException {
        front.send(ByteBuffer.wrap(data), sender);
        downCounts.sent(data.length);
    }

    private void fromTarget(UdpSessions.Session<DatagramChannel> session, byte[] data, long now) throws IOException {
        PairCondition condition = pair.down().get();
        if (!condition.passes()) {
            downCounts.droppedBroken();
            return;
        }
        synchronized (sessions) {
            sessions.answered(session, now);
        }
        if (!condition.shaped() && back.idle()) {
            sendToSender(session.sender(), data);
            return;
        }
        back.setConditions(condition.bitsPerSecond(), condition.delayMs(), condition.lossPercent());
        back.setLossRule(lossRule(condition));
        if (!back.offer(data, session.sender(), now)) {
            downCounts.droppedQueue();
        }
    }

    private void sendDue(long now) throws IOException {
        for (DatagramFlow.Datagram<UdpSessions.Session<DatagramChannel>> datagram : forward.due(now)) {
            sendToTarget(datagram.to(), datagram.data());
        }
        for (DatagramFlow.Datagram<InetSocketAddress> datagram : back.due(now)) {
            sendToSender(datagram.to(), datagram.data());
        }
        upCounts.lost(forward.lost() - lostForward);
        lostForward = forward.lost();
        downCounts.lost(back.lost() - lostBack);
        lostBack = back.lost();
        List<UdpSessions.Session<DatagramChannel>> expired;
        synchronized (sessions) {
            expired = sessions.expire(now);
        }
        for (UdpSessions.Session<DatagramChannel> session : expired) {
            session.socket().close();
        }
    }

    private void closeAll() {
        synchronized (sessions) {
            for (UdpSessions.Session<DatagramChannel> session : sessions.removeAll()) {
                closeQuietly(session.socket());
            }
        }
        closeQuietly(front);
        closeQuietly(selector);
        forward.close();
        back.close();
    }

    private static void closeQuietly(AutoCloseable closeable) {
        try {
            closeable.close();
        } catch (Exception e) {
            // closing at the end: nothing more to do
        }
    }

    /** Stops relaying and closes every socket; returns once the thread ended (at most a second). */
    @Override
    public void close() {
        closed = true;
        selector.wakeup();
        if (thread.isAlive()) {
            try {
                thread.join(1000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        } else {
            closeAll();
        }
    }
}
