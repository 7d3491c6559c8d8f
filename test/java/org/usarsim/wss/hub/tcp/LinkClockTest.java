package org.usarsim.wss.hub.tcp;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Logger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.Sockets;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.hub.core.CoreFixtures;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.hub.core.PairCondition;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.Airtime;
import org.usarsim.wss.shaping.JitterConfig;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * A link alone, between two robots on 127.0.0.1, on a clock the test gives: its loop takes the
 * time from the hub's clock, not the machine's. The clock here leaps 20 s at every reading, so
 * any wait the link measures by it is over at its next reading.
 */
class LinkClockTest {

    private final List<AutoCloseable> opened = new ArrayList<>();
    private final org.usarsim.wss.hub.core.PairStats stats = CoreFixtures.stats("A", "B", 0);
    private final AtomicBoolean ended = new AtomicBoolean();
    /** What the hub answers a link that reached its target: false, a step closed it meanwhile. */
    private volatile boolean establish = true;
    private final AtomicBoolean endedEstablished = new AtomicBoolean();

    @AfterEach
    void close() {
        Sockets.closeAllNewestFirst(opened);
    }

    @Test
    void aShapedLinkWaitsItsDelayOnTheHubsClock() throws Exception {
        // 10 s of delay, the most there is: on the machine's clock the bytes would come after every deadline here.
        PairCondition slow = new PairCondition(PairState.UP, 54_000_000, ShapingConfig.MAX_DELAY_MS);
        Shaping shaping = new Shaping(Airtime.shared(), CoreFixtures.condition(slow), CoreFixtures.condition(slow),
                ShapingConfig.DEFAULT_QUEUE_MS, JitterConfig.NONE);
        Robots robots = link(shaping);
        byte[] message = Sockets.randomBytes(64, 32);
        robots.source.getOutputStream().write(message);
        assertArrayEquals(message, Sockets.readExactlyBytes(robots.target.getInputStream(), 64));
        robots.target.getOutputStream().write(message);
        assertArrayEquals(message, Sockets.readExactlyBytes(robots.source.getInputStream(), 64), "and back");
    }

    @Test
    void aLinkWaitsForTheOtherSidesEndOnTheHubsClock() throws Exception {
        Robots robots = link(null);
        robots.source.getOutputStream().write(7);
        robots.source.shutdownOutput();
        assertEquals(7, robots.target.getInputStream().read());
        assertEquals(-1, robots.target.getInputStream().read(), "the source's end, passed on");
        // The target never ends its stream: the link gives up once 5 s have passed on the hub's clock.
        Wait.until("the link closed", ended::get);
    }

    /**
     * Issue 36: a link the hub does not announce (a FORCE down's step closed it while it connected
     * to its target) forwards nothing and ends as never established, uncounted.
     */
    @Test
    void aLinkTheHubDoesNotAnnounceForwardsNothingAndEndsUnestablished() throws Exception {
        establish = false;
        Robots robots = link(null);
        robots.source.getOutputStream().write(7);
        Wait.until("the link ended", ended::get);
        assertEquals(false, endedEstablished.get(), "never established: no CON_TERMINATED either");
        assertEquals(-1, readOrEnd(robots.target), "nothing forwarded to the target");
        assertEquals(0, stats.connections(), "not counted as a connection");
    }

    private static int readOrEnd(Socket socket) throws IOException {
        try {
            return socket.getInputStream().read();
        } catch (java.net.SocketException e) {
            return -1; // reset: ended all the same
        }
    }

    /** The two robots' sockets, each at its end of a link. */
    private record Robots(Socket source, Socket target) {
    }

    /** A link from a source robot to a target robot on 127.0.0.1, shaped as {@code shaping} says (null: not shaped), started. */
    private Robots link(Shaping shaping) throws IOException {
        ServerSocketChannel targetListener = open(ServerSocketChannel.open().bind(new InetSocketAddress("127.0.0.1", 0)));
        ServerSocketChannel wssPort = open(ServerSocketChannel.open().bind(new InetSocketAddress("127.0.0.1", 0)));
        Socket source = open(new Socket());
        source.connect(wssPort.getLocalAddress());
        SocketChannel accepted = open(wssPort.accept());
        WssPort port = CoreFixtures.port("A", "B", 5000, ((InetSocketAddress) wssPort.getLocalAddress()).getPort());
        Link link = new Link(new Hub(), port, accepted, (InetSocketAddress) targetListener.getLocalAddress(), 65536,
                SocketBuffers.of(0), new WssEventListener() {
                }, stats, new LeapingClock(), shaping);
        opened.add(link::close);
        link.start();
        Socket target = open(targetListener.accept().socket());
        source.setSoTimeout(5000);
        target.setSoTimeout(5000);
        return new Robots(source, target);
    }

    private <T extends AutoCloseable> T open(T closeable) {
        opened.add(closeable);
        return closeable;
    }

    /** A clock 20 s further on at every reading. */
    private static final class LeapingClock implements HubClock {
        private final AtomicInteger readings = new AtomicInteger();

        @Override
        public long nanoTime() {
            return readings.incrementAndGet() * 20_000_000_000L;
        }

        @Override
        public long wallMillis() {
            return readings.incrementAndGet() * 20_000L;
        }
    }

    /** All a link asks of the hub: its end is noted. */
    private final class Hub implements LinkHub {
        @Override
        public void accepted(WssPort port, int epoch, SocketChannel socket) {
            throw new UnsupportedOperationException();
        }

        @Override
        public boolean established(Link link, Runnable opened) {
            if (establish) {
                opened.run();
            }
            return establish;
        }

        @Override
        public void linkEnded(Link link, boolean wasEstablished) {
            endedEstablished.set(wasEstablished);
            ended.set(true);
        }

        @Override
        public KeepAlive keepAlive() {
            return KeepAlive.within(0);
        }

        @Override
        public Descriptors descriptors() {
            return new Descriptors(() -> false);
        }

        @Override
        public void note(Logger log, String category, InetAddress client, String message) {
        }

        @Override
        public void say(Logger log, String kind, InetAddress client, String message) {
        }

        @Override
        public void warn(Logger log, String category, InetAddress client, String message, Throwable cause) {
        }
    }
}
