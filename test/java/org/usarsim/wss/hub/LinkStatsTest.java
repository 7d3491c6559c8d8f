package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.hub.Sockets.randomBytes;
import static org.usarsim.wss.hub.Sockets.readExactlyBytes;

import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.core.CloseReason;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.hub.core.PairStats;
import org.usarsim.wss.hub.tcp.Closing;
import org.usarsim.wss.model.RobotLinkModel;

/**
 * The statistics of each pair of robots (issue 12), over real loopback sockets. The time up while
 * one of a pair's robots is gone, with the clock moved by hand: RobotGoneTest.
 */
@Tag("slow")
class LinkStatsTest {

    private ScriptedModel model;
    private TestHub server;
    private RobotLinkModel links;
    private TestRobot a;
    /** A's WSS port to B. */
    private int toB;
    private final List<java.io.Closeable> toClose = new ArrayList<>();
    private final ExecutorService pool = Executors.newCachedThreadPool();

    private void start(int portMemorySeconds) throws Exception {
        model = new ScriptedModel();
        server = new TestHub(model, TestHub.config(true, 65536, portMemorySeconds, 1000, 30));
        links = model.links();
    }

    @AfterEach
    void stop() throws Exception {
        pool.shutdownNow();
        for (int i = toClose.size() - 1; i >= 0; i--) {
            Closing.quietly(toClose.get(i));
        }
        server.close();
        assertTrue(pool.awaitTermination(5, TimeUnit.SECONDS), "the test's threads ended");
    }

    @Test
    void bytesCountedEqualBytesSentBothWaysOverTenPairs() throws Exception {
        start(600);
        int robots = 5; // every pair of 5 robots: 10 pairs
        String[] names = new String[robots];
        ServerSocket[] accepts = new ServerSocket[robots];
        TestRobot[] clients = new TestRobot[robots];
        for (int i = 0; i < robots; i++) {
            names[i] = "R" + i;
            clients[i] = robot("127.0.0." + (i + 1));
            accepts[i] = clients[i].initAccepting(names[i]);
        }
        Random random = new Random(12);
        List<long[]> expected = new ArrayList<>(); // first -> second, second -> first, in the pair's order
        List<Future<?>> transfers = new ArrayList<>();
        List<Socket> sockets = new ArrayList<>();
        for (int a = 0; a < robots; a++) {
            for (int b = a + 1; b < robots; b++) {
                // The source is the second robot of the pair half the time, to count both ways round.
                int source = random.nextBoolean() ? a : b;
                int target = source == a ? b : a;
                Socket out = clients[source].connect(clients[source].dns(names[target], 0));
                Socket in = accepts[target].accept();
                sockets.add(out);
                sockets.add(in);
                int forth = 1 + random.nextInt(400_000);
                int back = 1 + random.nextInt(400_000);
                expected.add(source == a ? new long[] {forth, back} : new long[] {back, forth});
                transfers.add(pool.submit(() -> exchange(out, in, forth, back)));
            }
        }
        for (Future<?> transfer : transfers) {
            transfer.get(20, TimeUnit.SECONDS);
        }
        for (Socket socket : sockets) {
            socket.close();
        }
        Wait.until("every link closed", () -> server.hub.snapshot().links().isEmpty());
        List<HubSnapshot.PairEntry> pairs = server.hub.snapshot().pairs();
        assertEquals(10, pairs.size(), pairs.toString());
        int i = 0;
        for (int a = 0; a < robots; a++) {
            for (int b = a + 1; b < robots; b++) {
                HubSnapshot.PairEntry pair = pairs.get(i);
                assertEquals(names[a], pair.first());
                assertEquals(names[b], pair.second());
                assertEquals(expected.get(i)[0], pair.bytesFirstToSecond(), pair.toString());
                assertEquals(expected.get(i)[1], pair.bytesSecondToFirst(), pair.toString());
                assertEquals(1, pair.connections(), pair.toString());
                assertEquals(PairState.UP, pair.state());
                assertEquals(0, pair.breaks());
                assertEquals(1.0, pair.upShare(), 1e-9);
                assertEquals(CloseReason.PEER_CLOSED.toString(), pair.lastClose());
                assertEquals(0.0, pair.strength(), 0.0, "the scripted model's strength");
                assertTrue(Double.isNaN(pair.distance()), "no positions: no distance");
                i++;
            }
        }
    }

    /** Sends {@code forth} bytes out and {@code back} bytes in, both at once, and checks what arrives. */
    private Void exchange(Socket out, Socket in, int forth, int back) throws Exception {
        byte[] there = randomBytes(forth, forth);
        byte[] home = randomBytes(back, back);
        Future<?> sending = pool.submit(() -> {
            out.getOutputStream().write(there);
            return null;
        });
        Future<?> answering = pool.submit(() -> {
            in.getOutputStream().write(home);
            return null;
        });
        assertArrayEquals(there, readExactlyBytes(in.getInputStream(), forth));
        assertArrayEquals(home, readExactlyBytes(out.getInputStream(), back));
        sending.get(10, TimeUnit.SECONDS);
        answering.get(10, TimeUnit.SECONDS);
        return null;
    }

    @Test
    void breaksAndResumesAreCountedWithTheShareOfTimeUpAndOneLogLinePerChange() throws Exception {
        start(600);
        ServerSocket bAccepts = robotsAAndB();
        connectAToB(bAccepts, 1);
        try (LogCapture log = LogCapture.of(Hub.class.getName(), Level.INFO)) {
            assertTrue(links.breakConnectionsForPair("B", "A"));
            Wait.until("the link closed out of range", () -> "out of range".equals(pair().lastClose()));
            HubSnapshot.PairEntry broken = pair();
            assertEquals(PairState.BROKEN, broken.state());
            assertEquals(1, broken.breaks());
            assertEquals(0, broken.resumes());
            assertTrue(broken.upShare() > 0 && broken.upShare() < 1, "up share " + broken.upShare());
            assertTrue(links.resumeConnectionsForPair("A", "B"));
            assertTrue(links.breakConnectionsForPair("A", "B"));
            assertTrue(links.resumeConnectionsForPair("A", "B"));
            HubSnapshot.PairEntry resumed = pair();
            assertEquals(PairState.UP, resumed.state());
            assertEquals(2, resumed.breaks());
            assertEquals(2, resumed.resumes());
            assertTrue(resumed.upShare() > 0 && resumed.upShare() < 1, "up share " + resumed.upShare());
            assertEquals(2, log.count(Level.INFO, "pair A - B: broken"), log.toString());
            assertEquals(2, log.count(Level.INFO, "pair A - B: up"), log.toString());
            // A break of a broken pair changes nothing, and says nothing.
            assertTrue(links.breakConnectionsForPair("A", "B"));
            links.breakConnectionsForPair("A", "B");
            assertEquals(3, pair().breaks());
            assertEquals(3, log.count(Level.INFO, "pair A - B: broken"), log.toString());
        }
        // A new connection after the resume is counted.
        links.resumeConnectionsForPair("A", "B");
        connectAToB(bAccepts, 2);
    }

    @Test
    void aKickIsTheLastCloseOfItsPairs() throws Exception {
        start(600);
        connectAToB(robotsAAndB(), 1);
        links.kickOutRobot("B");
        Wait.until("the link closed by the kick", () -> "kicked".equals(pair().lastClose()));
        assertEquals(PairState.GONE, pair().state(), "a kicked robot's pairs are not up (issue 26, item 4)");
        assertEquals("gone", pair().state().text());
    }

    @Test
    void aForcedPairShowsForcedAndItsConnectionsCloseAsForced() throws Exception {
        start(600);
        connectAToB(robotsAAndB(), 1);
        server.hub.force("B", "A", Force.DOWN);
        Wait.until("the link closed by the force", () -> "forced".equals(pair().lastClose()));
        assertEquals(PairState.FORCED_DOWN, pair().state());
        double downShare = pair().upShare();
        assertTrue(downShare < 1, "forced down is not up: " + downShare);
        links.breakConnectionsForPair("A", "B");
        assertEquals(PairState.FORCED_DOWN, pair().state(), "a force wins over the model");
        assertEquals(1, pair().breaks(), "the model's break is counted all the same");
        try (LogCapture log = LogCapture.of(Hub.class.getName(), Level.INFO)) {
            server.hub.force("A", "B", Force.UP);
            assertEquals(PairState.FORCED_UP, pair().state());
            server.hub.release("A", "B");
            assertEquals(PairState.BROKEN, pair().state(), "released: the model's last verdict");
            assertEquals(List.of("pair A - B: broken"), log.messages(Level.INFO), "the force said itself; the release's landing once");
        }
    }

    @Test
    void aServerStoppingIsTheLastCloseOfItsPairs() throws Exception {
        start(600);
        connectAToB(robotsAAndB(), 1);
        server.hub.close();
        Wait.until("the link closed by the stop", () -> "server stopped".equals(pair().lastClose()));
    }

    @Test
    void aTargetThatDoesNotAcceptIsTheLastClose() throws Exception {
        start(600);
        ServerSocket bAccepts = robotsAAndB();
        assertNull(pair().lastClose(), "no connection closed yet");
        bAccepts.close(); // B registered the port but no longer accepts on it
        toClose.add(a.connect(toB));
        Wait.until("the connection closed for want of a target", () -> "target refused".equals(pair().lastClose()));
        assertEquals(0, pair().connections(), "a connection never established is not counted");
    }

    @Test
    void thePairsOfARobotGoneAreForgottenWithItsPorts() throws Exception {
        start(0);
        TestRobot a = robot("127.0.0.1");
        TestRobot b = robot("127.0.0.2");
        TestRobot c = robot("127.0.0.3");
        a.init("A");
        b.initAccepting("B");
        c.initAccepting("C");
        a.dns("B", 0);
        a.dns("C", 0);
        assertEquals(2, server.hub.snapshot().pairs().size());
        c.close();
        Wait.until("C's pair forgotten", () -> server.hub.snapshot().pairs().size() == 1);
        assertEquals("B", pair().second());
    }

    @Test
    void theThroughputIsMeasuredBySampling() throws Exception {
        start(600);
        ServerSocket bAccepts = robotsAAndB();
        Socket out = a.connect(toB);
        Socket in = bAccepts.accept();
        toClose.add(out);
        toClose.add(in);
        AtomicBoolean sending = new AtomicBoolean(true);
        Future<?> sender = pool.submit(() -> {
            byte[] chunk = new byte[4096];
            while (sending.get()) {
                out.getOutputStream().write(chunk);
                Thread.sleep(1);
            }
            return null;
        });
        Future<?> reader = pool.submit(() -> {
            byte[] buffer = new byte[65536];
            while (in.getInputStream().read(buffer) >= 0) {
                // drain
            }
            return null;
        });
        Wait.until("a throughput A -> B", () -> pair().rateFirstToSecond() > 0);
        HubSnapshot.PairEntry measured = pair();
        assertEquals(0.0, measured.rateSecondToFirst(), "nothing sent B -> A");
        assertTrue(measured.rateFirstToSecond() <= measured.bytesFirstToSecond() / (PairStats.RATE_SPAN_NS / 1e9),
                "a rate over at least RATE_SPAN_NS is at most what was sent in it: " + measured);
        sending.set(false);
        sender.get(5, TimeUnit.SECONDS);
        out.close();
        reader.get(5, TimeUnit.SECONDS);
    }

    @Test
    void bytesSentBeforeTheFirstSampleShowAsAThroughput() throws Exception {
        // Headless, the first statsInterval table is the first sample: a transfer before it must not vanish from the rates.
        start(600);
        ServerSocket bAccepts = robotsAAndB();
        try (Socket out = a.connect(toB); Socket in = bAccepts.accept()) {
            exchange(out, in, 300_000, 100_000);
        }
        Wait.until("the bytes sent before the first sample measured both ways",
                () -> pair().rateFirstToSecond() > 0 && pair().rateSecondToFirst() > 0);
        HubSnapshot.PairEntry measured = pair();
        double span = PairStats.RATE_SPAN_NS / 1e9;
        assertTrue(measured.rateFirstToSecond() <= 300_000 / span && measured.rateSecondToFirst() <= 100_000 / span,
                "over at least RATE_SPAN_NS: at most what was sent in it " + measured);
    }

    @Test
    void aPairBrokenWhenARobotWasKickedIsUpWhenItComesBack() throws Exception {
        start(600);
        robotsAAndB();
        links.breakConnectionsForPair("A", "B");
        assertEquals(PairState.BROKEN, pair().state());
        links.kickOutRobot("B"); // the hub forgets the break with the robot
        try (LogCapture log = LogCapture.of(Hub.class.getName(), Level.INFO)) {
            TestRobot b = robot("127.0.0.2");
            ServerSocket bAccepts = b.initAccepting("B");
            toB = a.dns("B", 0);
            connectAToB(bAccepts, 1); // forwarded again: the pair is up
            assertEquals(PairState.UP, pair().state(), pair().toString());
            assertEquals(1, log.count(Level.INFO, "pair A - B: up"), log.toString());
        }
    }

    @Test
    void aPairIsNotUpWhileOneOfItsRobotsIsGone() throws Exception {
        start(600);
        a = robot("127.0.0.1");
        TestRobot b = robot("127.0.0.2");
        a.init("A");
        b.initAccepting("B");
        toB = a.dns("B", 0);
        assertEquals(1.0, pair().upShare(), 1e-9);
        b.close();
        Wait.until("B gone", () -> server.hub.snapshot().robots().size() == 1);
        Wait.until("the time B is gone is not time up", () -> pair().upShare() < 0.5);
        assertEquals(PairState.GONE, pair().state(), "shown gone, not up, while B is not registered (issue 26)");
        TestRobot back = robot("127.0.0.2");
        back.initAccepting("B");
        double whenBack = pair().upShare();
        Wait.until("up again once B is back", () -> pair().upShare() > whenBack);
        assertEquals(PairState.UP, pair().state(), "the model did not break the pair: up again with B back");
    }

    /** Robot A, and robot B accepting on one port; returns B's accepting socket and sets {@link #a} and {@link #toB}. */
    private ServerSocket robotsAAndB() throws Exception {
        a = robot("127.0.0.1");
        TestRobot b = robot("127.0.0.2");
        a.init("A");
        ServerSocket bAccepts = b.initAccepting("B");
        toB = a.dns("B", 0);
        return bAccepts;
    }

    /** A connection A -> B through the WSS, established. */
    private void connectAToB(ServerSocket bAccepts, long connections) throws Exception {
        toClose.add(a.connect(toB));
        toClose.add(bAccepts.accept());
        Wait.until("the link established", () -> pair().connections() == connections);
    }

    private HubSnapshot.PairEntry pair() {
        List<HubSnapshot.PairEntry> pairs = server.hub.snapshot().pairs();
        assertTrue(!pairs.isEmpty(), "a pair seen");
        return pairs.get(0);
    }

    private TestRobot robot(String address) throws Exception {
        TestRobot robot = server.robotAt(address);
        toClose.add(robot::close);
        return robot;
    }
}
