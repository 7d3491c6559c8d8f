package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.usarsim.wss.hub.Sockets.assertClosedByPeer;
import static org.usarsim.wss.hub.Sockets.linkThreads;
import static org.usarsim.wss.hub.Sockets.listeningSockets;
import static org.usarsim.wss.hub.Sockets.randomBytes;
import static org.usarsim.wss.hub.Sockets.readExactly;
import static org.usarsim.wss.hub.Sockets.readExactlyBytes;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.BindException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.WssEventListener;

/**
 * What a propagation model does to robots and their links (break, resume, kick, the list of
 * robots), what a lost control connection does, and what it all costs in threads and descriptors.
 * Everything over real loopback sockets, driven by a {@link ScriptedModel}.
 */
@Tag("slow")
class LinkLifecycleTest {

    private ScriptedModel model;
    private TestHub server;
    private RobotLinkModel links;
    private final List<AutoCloseable> toClose = new ArrayList<>();
    private final ExecutorService pool = Executors.newCachedThreadPool();

    @TempDir
    Path tempDir;

    @BeforeEach
    void start() throws Exception {
        model = new ScriptedModel();
        server = new TestHub(model, true, 65536);
        links = model.links();
        assertTrue(links != null, "the hub gave the model a RobotLinkModel");
    }

    @AfterEach
    void stop() throws Exception {
        Sockets.closeAllNewestFirst(toClose);
        server.close();
        pool.shutdownNow();
        assertTrue(pool.awaitTermination(5, TimeUnit.SECONDS));
    }

    // ---- 1. break ----

    @Test
    void breakStopsEveryPortOfThePairAtOnceClosesItsConnectionsAndKeepsTheNumbers() throws Exception {
        TestRobot r1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.2");
        TestRobot r3 = robot("127.0.0.3");
        ServerSocket r1First = r1.listen();
        ServerSocket r1Second = r1.listen();
        ServerSocket r2Accepts = r2.listen();
        ServerSocket r3Accepts = r3.listen();
        r1.init("R1", r1First.getLocalPort(), r1Second.getLocalPort());
        r2.init("R2", r2Accepts.getLocalPort());
        r3.init("R3", r3Accepts.getLocalPort());

        int r2ToR1First = r2.dns("R1", r1First.getLocalPort());
        int r2ToR1Second = r2.dns("R1", r1Second.getLocalPort());
        int r1ToR2 = r1.dns("R2", 0);
        int r3ToR1 = r3.dns("R1", 0);
        int r1ToR3 = r1.dns("R3", 0);

        Conn[] pair = {open(r2, r2ToR1First, r1First), open(r2, r2ToR1Second, r1Second), open(r1, r1ToR2, r2Accepts)};
        Conn[] others = {open(r3, r3ToR1, r1First), open(r1, r1ToR3, r3Accepts)};
        for (Conn conn : pair) {
            assertPasses(conn, "before");
        }
        for (Conn conn : others) {
            assertPasses(conn, "before");
        }

        assertTrue(links.breakConnectionsForPair("R1", "R2"), "the first break changes something");
        // Right after the call: every port of the pair, both directions, every target port, refuses.
        assertRefused(r2, r2ToR1First, "R2 -> R1 first port");
        assertRefused(r2, r2ToR1Second, "R2 -> R1 second port");
        assertRefused(r1, r1ToR2, "R1 -> R2");
        // Every established connection of the pair is closed at both ends.
        for (Conn conn : pair) {
            assertClosedByPeer(conn.source, "the source's end of " + conn);
            assertClosedByPeer(conn.target, "the target's end of " + conn);
        }
        // The numbers are kept, and still refuse.
        assertEquals(r2ToR1First, r2.dns("R1", r1First.getLocalPort()));
        assertEquals(r2ToR1First, r2.dns("R1", 0));
        assertEquals(r2ToR1Second, r2.dns("R1", r1Second.getLocalPort()));
        assertEquals(r1ToR2, r1.dns("R2", 0));
        assertRefused(r2, r2ToR1First, "R2 -> R1 first port after DNS");
        assertRefused(r2, r2ToR1Second, "R2 -> R1 second port after DNS");
        assertRefused(r1, r1ToR2, "R1 -> R2 after DNS");

        // The other pair is untouched: its connections pass data, its ports accept.
        for (Conn conn : others) {
            assertPasses(conn, "after the break");
        }
        assertPasses(open(r3, r3ToR1, r1First), "new R3 -> R1");
        assertPasses(open(r1, r1ToR3, r3Accepts), "new R1 -> R3");

        assertFalse(links.breakConnectionsForPair("R1", "R2"), "a second break has nothing to change");
        assertFalse(links.breakConnectionsForPair("R2", "R1"), "a pair has no direction");
        Wait.until("the pair's link threads ended", () -> linkThreads() == 4);
    }

    @Test
    void everyBreakRefusesAtOnceAndKeepsTheNumberReserved() throws Exception {
        TestRobot r1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.2");
        ServerSocket r1Accepts = r1.initAccepting("R1");
        r2.init("R2", 6000);
        int port = r2.dns("R1", 0);
        int rounds = 500;
        int accepted = 0;
        int taken = 0;
        for (int i = 0; i < rounds; i++) {
            assertTrue(links.breakConnectionsForPair("R1", "R2"), "break " + i);
            // Right after the call returns, the port refuses...
            try {
                r2.connect(port).close();
                accepted++;
            } catch (ConnectException refused) {
                // as it should
            } catch (SocketException reset) {
                accepted++; // the connect went through, and then the WSS reset it
            }
            // ...and its number stays reserved: another socket cannot bind it.
            try (ServerSocket thief = new ServerSocket()) {
                thief.setReuseAddress(false);
                thief.bind(new InetSocketAddress("127.0.0.1", port));
                taken++;
            } catch (BindException reserved) {
                // as it should
            }
            links.resumeConnectionsForPair("R1", "R2");
        }
        assertEquals(0, accepted, "connects accepted on WSS port " + port + " right after breakConnectionsForPair returned, in "
                + rounds + " breaks");
        assertEquals(0, taken, "times WSS port " + port + "'s number could be bound by another socket while broken, in "
                + rounds + " breaks");
    }

    // ---- 2. resume ----

    @Test
    void resumeListensAgainOnTheSameNumbersAndNoResumeIsLostInARace() throws Exception {
        TestRobot r1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.2");
        ServerSocket r1First = r1.listen();
        ServerSocket r1Second = r1.listen();
        ServerSocket r2Accepts = r2.listen();
        r1.init("R1", r1First.getLocalPort(), r1Second.getLocalPort());
        r2.init("R2", r2Accepts.getLocalPort());
        int r2ToR1First = r2.dns("R1", 0);
        int r2ToR1Second = r2.dns("R1", r1Second.getLocalPort());
        int r1ToR2 = r1.dns("R2", 0);

        assertTrue(links.breakConnectionsForPair("R2", "R1"));
        assertRefused(r2, r2ToR1First, "broken");
        assertTrue(links.resumeConnectionsForPair("R1", "R2"), "the first resume changes something");
        assertPasses(open(r2, r2ToR1First, r1First), "R2 -> R1 first port after resume");
        assertPasses(open(r2, r2ToR1Second, r1Second), "R2 -> R1 second port after resume");
        assertPasses(open(r1, r1ToR2, r2Accepts), "R1 -> R2 after resume");
        assertFalse(links.resumeConnectionsForPair("R1", "R2"), "a second resume has nothing to change");
        assertFalse(links.resumeConnectionsForPair("R2", "R1"), "nor in the other order");
        assertEquals(r2ToR1First, r2.dns("R1", 0));
        assertEquals(r2ToR1Second, r2.dns("R1", r1Second.getLocalPort()));
        assertEquals(r1ToR2, r1.dns("R2", 0));

        // From here on, each target greets every connection it gets with one byte and closes it.
        greet(r1First);
        greet(r1Second);
        greet(r2Accepts);
        // 200 quick pairs on one thread, each followed by a check that every port forwards again.
        for (int i = 0; i < 200; i++) {
            assertTrue(links.breakConnectionsForPair("R1", "R2"), "break " + i);
            assertTrue(links.resumeConnectionsForPair("R1", "R2"), "resume " + i);
            assertForwarded(r2, r2ToR1First, "R2 -> R1 first port after resume " + i);
            assertForwarded(r2, r2ToR1Second, "R2 -> R1 second port after resume " + i);
            assertForwarded(r1, r1ToR2, "R1 -> R2 after resume " + i);
        }
        // 200 quick pairs back to back.
        for (int i = 0; i < 200; i++) {
            links.breakConnectionsForPair("R1", "R2");
            links.resumeConnectionsForPair("R1", "R2");
        }
        assertGreeted(r1, r2, r2ToR1First, r2ToR1Second, r1ToR2, "after 200 in a row");

        // Two threads racing, each ending with a resume: the last call is a resume, so the ports listen.
        CountDownLatch go = new CountDownLatch(1);
        List<Future<?>> racers = new ArrayList<>();
        for (int t = 0; t < 2; t++) {
            boolean flip = t == 1;
            racers.add(pool.submit(() -> {
                go.await();
                for (int i = 0; i < 200; i++) {
                    links.breakConnectionsForPair(flip ? "R2" : "R1", flip ? "R1" : "R2");
                    links.resumeConnectionsForPair(flip ? "R1" : "R2", flip ? "R2" : "R1");
                }
                return null;
            }));
        }
        go.countDown();
        for (Future<?> racer : racers) {
            racer.get(20, TimeUnit.SECONDS);
        }
        assertGreeted(r1, r2, r2ToR1First, r2ToR1Second, r1ToR2, "after the race");
        assertFalse(links.resumeConnectionsForPair("R1", "R2"), "after the race nothing is left to resume");
        for (int port : new int[] {r2ToR1First, r2ToR1Second, r1ToR2}) {
            Wait.until("one listening socket on WSS port " + port, () -> listeningSockets(port) == 1);
        }
    }

    // ---- 3. kick ----

    @Test
    void kickClosesEverythingOfTheRobotDeregistersItAndForgetsItsPorts() throws Exception {
        TestRobot r1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.2");
        TestRobot r3 = robot("127.0.0.3");
        ServerSocket r1Accepts = r1.listen();
        ServerSocket r2Accepts = r2.listen();
        ServerSocket r3Accepts = r3.listen();
        r1.init("R1", r1Accepts.getLocalPort());
        r2.init("R2", r2Accepts.getLocalPort());
        r3.init("R3", r3Accepts.getLocalPort());
        int r2ToR1 = r2.dns("R1", 0);
        int r1ToR2 = r1.dns("R2", 0);
        int r3ToR1 = r3.dns("R1", 0);
        int r2ToR3 = r2.dns("R3", 0);
        Conn[] ofR1 = {open(r2, r2ToR1, r1Accepts), open(r1, r1ToR2, r2Accepts), open(r3, r3ToR1, r1Accepts)};
        Conn notR1 = open(r2, r2ToR3, r3Accepts);
        for (Conn conn : ofR1) {
            assertPasses(conn, "before");
        }
        assertPasses(notR1, "before");

        links.kickOutRobot("R1");

        for (Conn conn : ofR1) {
            assertClosedByPeer(conn.source, "the source's end of " + conn);
            assertClosedByPeer(conn.target, "the target's end of " + conn);
        }
        // The control connection is closed without a message: end of stream, not one byte before it.
        byte[] buffer = new byte[256];
        int read;
        try {
            read = r1.control.getInputStream().read(buffer);
        } catch (SocketTimeoutException e) {
            throw new AssertionError("R1's control connection is still open " + TestRobot.TIMEOUT_MS + " ms after the kick", e);
        }
        assertEquals(-1, read, "R1's control connection: end of stream, and no message before it"
                + (read > 0 ? " (got '" + new String(buffer, 0, read, StandardCharsets.UTF_8) + "')" : ""));
        // Deregistered.
        assertFalse(links.getListOfRegisteredRobots().contains("R1"));
        assertEquals("SS {Robot R1} {Strength NaN} {Error Robot.Does.Not.Exist}", r2.ask("GETSS {Robot R1}"));
        assertEquals("DNSREPLY {Robot R1} {Port -1} {Error NoSuchRobot}", r2.ask("DNS {Robot R1}"));
        // Its ports are gone.
        assertRefused(r2, r2ToR1, "R2 -> R1 after the kick");
        assertRefused(r1, r1ToR2, "R1 -> R2 after the kick");
        assertRefused(r3, r3ToR1, "R3 -> R1 after the kick");
        // Other robots are untouched.
        assertPasses(notR1, "after the kick");

        // The name is free; the old numbers stay closed, even with both robots registered again.
        TestRobot again = robot("127.0.0.1");
        again.init("R1", r1Accepts.getLocalPort());
        assertEquals(List.of("R1", "R2", "R3"), links.getListOfRegisteredRobots());
        assertRefused(r2, r2ToR1, "the forgotten R2 -> R1 number after R1 came back");
        assertRefused(again, r1ToR2, "the forgotten R1 -> R2 number after R1 came back");
        assertRefused(r3, r3ToR1, "the forgotten R3 -> R1 number after R1 came back");
        assertEquals("SS {Robot R1} {Strength 0}", r2.ask("GETSS {Robot R1}"));
        // A fresh DNS works and data flows.
        assertPasses(open(r2, r2.dns("R1", 0), r1Accepts), "R2 -> R1 on a fresh number");
        assertPasses(open(again, again.dns("R2", 0), r2Accepts), "R1 -> R2 on a fresh number");
    }

    @Test
    void aKickForgetsTheRobotsBreaks() throws Exception {
        TestRobot r1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.2");
        ServerSocket r1Accepts = r1.initAccepting("R1");
        r2.init("R2", 6000);
        int before = r2.dns("R1", 0);
        assertTrue(links.breakConnectionsForPair("R1", "R2"));
        assertRefused(r2, before, "broken");
        links.kickOutRobot("R1");
        TestRobot again = robot("127.0.0.1");
        again.init("R1", r1Accepts.getLocalPort());
        assertPasses(open(r2, r2.dns("R1", 0), r1Accepts), "R2 -> R1 after the kick and a new INIT");
        assertFalse(links.resumeConnectionsForPair("R1", "R2"), "nothing was left broken");
    }

    // ---- 4. the list of robots ----

    @Test
    void theListOfRegisteredRobotsIsSorted() throws Exception {
        assertEquals(List.of(), links.getListOfRegisteredRobots());
        TestRobot b = robot("127.0.0.1");
        TestRobot r10 = robot("127.0.0.1");
        TestRobot a1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.1");
        b.init("b", 5000);
        r10.init("R10", 5000);
        List<String> snapshot = links.getListOfRegisteredRobots();
        a1.init("A1", 5000);
        r2.init("R2", 5000);
        assertEquals(List.of("R10", "b"), snapshot, "a snapshot, sorted");
        assertEquals(List.of("A1", "R10", "R2", "b"), links.getListOfRegisteredRobots());
        r10.control.close();
        Wait.until("R10 is deregistered", () -> links.getListOfRegisteredRobots().size() == 3);
        assertEquals(List.of("A1", "R2", "b"), links.getListOfRegisteredRobots());
        links.kickOutRobot("A1");
        assertEquals(List.of("R2", "b"), links.getListOfRegisteredRobots());
    }

    // ---- 5. a control connection closes ----

    @Test
    void aClosedControlConnectionStopsThePortsKeepsTheNumbersAndLetsLinksLive() throws Exception {
        TestRobot r1 = robot("127.0.0.2");
        TestRobot r2 = robot("127.0.0.1");
        ServerSocket r1Accepts = r1.listen();
        ServerSocket r2Accepts = r2.listen();
        r1.init("R1", r1Accepts.getLocalPort());
        r2.init("R2", r2Accepts.getLocalPort());
        int r2ToR1 = r2.dns("R1", 0);
        int r1ToR2 = r1.dns("R2", 0);
        Conn toR1 = open(r2, r2ToR1, r1Accepts);
        Conn fromR1 = open(r1, r1ToR2, r2Accepts);
        assertPasses(toR1, "before");
        assertPasses(fromR1, "before");

        r1.control.close();
        Wait.until("R1 is deregistered", () -> !links.getListOfRegisteredRobots().contains("R1"));
        assertEquals("SS {Robot R1} {Strength NaN} {Error Robot.Does.Not.Exist}", r2.ask("GETSS {Robot R1}"));
        assertRefused(r2, r2ToR1, "R2 -> R1 without R1");
        assertRefused(r1, r1ToR2, "R1 -> R2 without R1");
        // The established connections live on, both ways.
        for (int i = 0; i < 3; i++) {
            assertPasses(toR1, "after the control connection closed " + i);
            assertPasses(fromR1, "after the control connection closed " + i);
        }
        Wait.until("two links live on", () -> linkThreads() == 2);

        // INIT of the same name: the same numbers listen again.
        TestRobot again = robot("127.0.0.2");
        again.init("R1", r1Accepts.getLocalPort());
        assertPasses(open(r2, r2ToR1, r1Accepts), "R2 -> R1 after INIT, before any DNS");
        assertPasses(open(again, r1ToR2, r2Accepts), "R1 -> R2 after INIT, before any DNS");
        assertEquals(r2ToR1, r2.dns("R1", 0));
        assertEquals(r1ToR2, again.dns("R2", 0));
        // The old connections still pass data, until an end closes them.
        assertPasses(toR1, "after INIT");
        assertPasses(fromR1, "after INIT");
        toR1.source.close();
        assertClosedByPeer(toR1.target, "the target after the source closed");
        fromR1.target.close();
        assertClosedByPeer(fromR1.source, "the source after the target closed");
    }

    @Test
    void aBreakHoldsAcrossALostControlConnectionAndANewInit() throws Exception {
        TestRobot r1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.2");
        ServerSocket r1Accepts = r1.initAccepting("R1");
        r2.init("R2", 6000);
        int r2ToR1 = r2.dns("R1", 0);
        assertTrue(links.breakConnectionsForPair("R1", "R2"));
        r1.control.close();
        Wait.until("R1 is deregistered", () -> !links.getListOfRegisteredRobots().contains("R1"));
        TestRobot again = robot("127.0.0.1");
        again.init("R1", r1Accepts.getLocalPort());
        assertRefused(r2, r2ToR1, "still broken after the new INIT");
        assertEquals(r2ToR1, r2.dns("R1", 0));
        assertRefused(r2, r2ToR1, "still broken after a DNS");
        assertTrue(links.resumeConnectionsForPair("R1", "R2"));
        assertPasses(open(r2, r2ToR1, r1Accepts), "after the resume");
    }

    @Test
    void aBreakOfRobotsNotYetRegisteredAppliesWhenTheyRegister() throws Exception {
        assertTrue(links.breakConnectionsForPair("R1", "R2"), "a new broken mark is a change");
        assertFalse(links.breakConnectionsForPair("R1", "R2"));
        TestRobot r1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.2");
        ServerSocket r1Accepts = r1.initAccepting("R1");
        r2.init("R2", 6000);
        int r2ToR1 = r2.dns("R1", 0);
        assertRefused(r2, r2ToR1, "broken before it was registered");
        assertTrue(links.resumeConnectionsForPair("R2", "R1"));
        assertPasses(open(r2, r2ToR1, r1Accepts), "after the resume");
    }

    // ---- 6. the model forbids ----

    @Test
    void aForbiddenPairGetsANumberThatRefusesUntilResumedAndAConnectionWhileForbiddenIsClosed() throws Exception {
        TestRobot r1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.2");
        ServerSocket r1Accepts = r1.listen();
        ServerSocket r2Accepts = r2.listen();
        r1.init("R1", r1Accepts.getLocalPort());
        r2.init("R2", r2Accepts.getLocalPort());
        model.strength("R2", "R1", -67.12345);
        assertEquals("SS {Robot R1} {Strength -67.1235}", r2.ask("GETSS {Robot R1}"), "the scripted strength");

        model.allow("R2", "R1", false);
        int r2ToR1 = r2.dns("R1", 0);
        assertRefused(r2, r2ToR1, "forbidden at DNS");
        assertEquals(r2ToR1, r2.dns("R1", 0), "the same number at the next DNS");
        assertRefused(r2, r2ToR1, "still forbidden");
        // The model decides per direction.
        int r1ToR2 = r1.dns("R2", 0);
        assertPasses(open(r1, r1ToR2, r2Accepts), "R1 -> R2 is allowed");

        model.allow("R2", "R1", true);
        assertRefused(r2, r2ToR1, "a changed answer alone opens no port");
        assertTrue(links.resumeConnectionsForPair("R1", "R2"), "the resume opens a port");
        assertPasses(open(r2, r2ToR1, r1Accepts), "R2 -> R1 after the resume");
        assertEquals(r2ToR1, r2.dns("R1", 0));
        assertFalse(links.resumeConnectionsForPair("R1", "R2"));

        // The answer flips to false after the DNS, with no break: the port listens, a connection is closed at once.
        model.allow("R2", "R1", false);
        for (int i = 0; i < 3; i++) {
            try (Socket refused = r2.connect(r2ToR1)) {
                assertClosedByPeer(refused, "a connection while the model forbids the pair, " + i);
            }
        }
        model.allow("R2", "R1", true);
        // Nothing was forwarded for the refused ones: the first connection R1 accepts is this one.
        assertPasses(open(r2, r2ToR1, r1Accepts), "allowed again");
    }

    @Test
    void aDnsThatGetsTrueOpensAPortThatAFalseDnsLeftClosed() throws Exception {
        TestRobot r1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.2");
        ServerSocket r1Accepts = r1.initAccepting("R1");
        r2.init("R2", 6000);
        model.allow("R2", "R1", false);
        int r2ToR1 = r2.dns("R1", 0);
        assertRefused(r2, r2ToR1, "forbidden at DNS");
        model.allow("R2", "R1", true);
        assertEquals(r2ToR1, r2.dns("R1", 0));
        assertPasses(open(r2, r2ToR1, r1Accepts), "after a DNS that got true");
    }

    // ---- 7. events ----

    @Test
    void eventsReachListenersAndTheCsvLog() throws Exception {
        Recorder recorder = new Recorder();
        CsvEventLog log = CsvEventLog.create(tempDir);
        server.hub.addListener(recorder);
        server.hub.addListener(log);

        TestRobot r1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.2");
        ServerSocket r1Accepts = r1.listen();
        ServerSocket r1Other = r1.listen();
        ServerSocket r2Accepts = r2.listen();
        int a = r1Accepts.getLocalPort();
        int b = r1Other.getLocalPort();
        int c = r2Accepts.getLocalPort();
        r1.init("R1", a, b);
        r2.init("R2", c);
        long toR1 = 0;
        long toR2 = 0;

        // A connection R2 -> R1 with a lot one way and a little the other, closed by the source.
        Conn first = open(r2, r2.dns("R1", 0), r1Accepts);
        byte[] big = randomBytes(100_000, 7);
        byte[] small = randomBytes(3_333, 8);
        first.source.getOutputStream().write(big);
        assertArrayEquals(big, readExactlyBytes(first.target.getInputStream(), big.length));
        first.target.getOutputStream().write(small);
        assertArrayEquals(small, readExactlyBytes(first.source.getInputStream(), small.length));
        toR1 += big.length;
        toR2 += small.length;
        first.source.close();
        // The target gets the end of stream after the last byte, and closes its end as clients do.
        assertEquals(-1, first.target.getInputStream().read());
        first.target.close();
        Wait.until("the first connection terminated", () -> recorder.count("CON_TERMINATED,R2,R1," + a) == 1);

        // A connection R1 -> R2, closed by a break.
        Conn second = open(r1, r1.dns("R2", 0), r2Accepts);
        assertPasses(second, "second");
        toR2 += "second>".length();
        toR1 += "<second".length();
        assertTrue(links.breakConnectionsForPair("R1", "R2"));
        Wait.until("the broken connection terminated", () -> recorder.count("CON_TERMINATED,R1,R2," + c) == 1);
        assertTrue(links.resumeConnectionsForPair("R1", "R2"));

        // R1's control connection closes; R1 registers again.
        r1.control.close();
        Wait.until("R1 deregistered", () -> recorder.count("DEREGISTERED,R1") == 1);
        TestRobot again = robot("127.0.0.1");
        again.init("R1", b);

        // A connection to R1's second port, open while R1 is kicked.
        Conn third = open(r2, r2.dns("R1", 0), r1Other);
        assertPasses(third, "third");
        toR1 += "third>".length();
        toR2 += "<third".length();
        links.kickOutRobot("R1");
        Wait.until("the kicked robot's connection terminated", () -> recorder.count("CON_TERMINATED,R2,R1," + b) == 1);
        Wait.until("every link thread ended", () -> linkThreads() == 0);
        server.hub.removeListener(recorder);
        server.hub.removeListener(log);
        log.close();

        List<String> events = recorder.events();
        List<String> expectedOrder = List.of(
                "REGISTERED,R1,127.0.0.1," + a + ":" + b,
                "REGISTERED,R2,127.0.0.2," + c,
                "CON_ESTABLISHED,R2,R1," + a,
                "CON_TERMINATED,R2,R1," + a,
                "CON_ESTABLISHED,R1,R2," + c,
                "CON_TERMINATED,R1,R2," + c,
                "DEREGISTERED,R1",
                "REGISTERED,R1,127.0.0.1," + b,
                "CON_ESTABLISHED,R2,R1," + b);
        List<String> notData = events.stream().filter(e -> !e.startsWith("DATA_SENT,")).toList();
        assertEquals(expectedOrder, notData.subList(0, expectedOrder.size()), String.join("\n", events));
        assertEquals(List.of("CON_TERMINATED,R2,R1," + b, "DEREGISTERED,R1"),
                notData.subList(expectedOrder.size(), notData.size()).stream().sorted().toList(),
                "the kick: the connection's end and the deregistration, in either order");
        assertEquals(toR1, recorder.sent("R2", "R1"), "bytes R2 -> R1");
        assertEquals(toR2, recorder.sent("R1", "R2"), "bytes R1 -> R2");
        assertTrue(events.stream().filter(e -> e.startsWith("DATA_SENT,")).allMatch(e -> Integer.parseInt(e.split(",")[3]) > 0),
                "no empty chunk reported");

        // The CSV log has the same events, as lines with the time of day in the second field.
        List<String> lines = Files.readAllLines(log.file());
        String time = "\\d\\d:\\d\\d:\\d\\d\\.\\d{3}";
        List<String> withoutTime = new ArrayList<>();
        for (String line : lines) {
            String[] fields = line.split(",", -1);
            assertTrue(fields.length >= 3 && fields[1].matches(time), "a CSV line with a time: " + line);
            List<String> kept = new ArrayList<>(List.of(fields));
            kept.remove(1);
            withoutTime.add(String.join(",", kept));
        }
        assertEquals(events.stream().sorted().toList(), withoutTime.stream().sorted().toList(),
                "the CSV log holds the same events");
        // All but the kick's two events (fired on two threads) come in a fixed order, in both.
        assertEquals(events.subList(0, events.size() - 2), withoutTime.subList(0, withoutTime.size() - 2),
                "the CSV log holds the events in the same order");
    }

    // ---- 8. resource hygiene ----

    @Test
    void shortConnectionsAndABreakLeaveNoThreadsNorDescriptorsBehind() throws Exception {
        TestRobot r1 = robot("127.0.0.1");
        TestRobot r2 = robot("127.0.0.2");
        ServerSocket r1Accepts = r1.initAccepting("R1");
        r2.init("R2", 6000);
        int port = r2.dns("R1", 0);
        for (int i = 0; i < 20; i++) {
            shortConnection(r2, port, r1Accepts, i);
        }
        Wait.until("the warm-up's link threads ended", () -> linkThreads() == 0);
        long before = Wait.settle("descriptors settle", Sockets::openDescriptors, n -> true);

        for (int i = 0; i < 300; i++) {
            shortConnection(r2, port, r1Accepts, i);
        }
        Conn open = open(r2, port, r1Accepts);
        assertPasses(open, "before the break");
        assertTrue(links.breakConnectionsForPair("R1", "R2"));
        assertClosedByPeer(open.source, "the source after the break");
        assertClosedByPeer(open.target, "the target after the break");
        open.source.close();
        open.target.close();
        assertRefused(r2, port, "broken");
        assertTrue(links.resumeConnectionsForPair("R1", "R2"));
        shortConnection(r2, port, r1Accepts, 300);

        Wait.until("every link thread ended", () -> linkThreads() == 0);
        Wait.until("one listening socket on the WSS port", () -> listeningSockets(port) == 1);
        long after = Wait.settle("descriptors return to their level", Sockets::openDescriptors,
                n -> n <= before + 5);
        assertTrue(after <= before + 5, "open descriptors before " + before + ", after " + after);
    }

    // ---- helpers ----

    /** A forwarded connection: the source robot's socket and the socket the target accepted. */
    private record Conn(Socket source, Socket target, String name) {
        @Override
        public String toString() {
            return name;
        }
    }

    private TestRobot robot(String address) throws Exception {
        TestRobot robot = server.robotAt(address);
        toClose.add(robot);
        return robot;
    }

    /** Connects through a WSS port and accepts the forwarded connection at the target. */
    private Conn open(TestRobot source, int wssPort, ServerSocket targetAccepts) throws IOException {
        Socket out = source.connect(wssPort);
        toClose.add(out);
        Socket in;
        try {
            in = targetAccepts.accept();
        } catch (SocketTimeoutException e) {
            throw new AssertionError("the target was not connected through WSS port " + wssPort, e);
        }
        toClose.add(in);
        in.setSoTimeout(TestRobot.TIMEOUT_MS);
        return new Conn(out, in, source.address + " -> WSS port " + wssPort + " -> " + targetAccepts.getLocalSocketAddress());
    }

    /** Bytes pass both ways, unchanged. */
    private static void assertPasses(Conn conn, String tag) throws IOException {
        byte[] there = (tag + ">").getBytes(StandardCharsets.UTF_8);
        byte[] back = ("<" + tag).getBytes(StandardCharsets.UTF_8);
        conn.source.getOutputStream().write(there);
        assertEquals(tag + ">", readExactly(conn.target.getInputStream(), there.length), conn + ": " + tag);
        conn.target.getOutputStream().write(back);
        assertEquals("<" + tag, readExactly(conn.source.getInputStream(), back.length), conn + ": " + tag);
    }

    private static void assertRefused(TestRobot from, int wssPort, String what) {
        assertThrows(ConnectException.class, () -> from.connect(wssPort).close(), "WSS port " + wssPort + " refuses: " + what);
    }

    private static void assertGreeted(TestRobot r1, TestRobot r2, int r2ToR1First, int r2ToR1Second, int r1ToR2,
            String when) throws IOException {
        assertForwarded(r2, r2ToR1First, "R2 -> R1 first port " + when);
        assertForwarded(r2, r2ToR1Second, "R2 -> R1 second port " + when);
        assertForwarded(r1, r1ToR2, "R1 -> R2 " + when);
    }

    /** From now on, every connection the robot's socket accepts gets one byte, '!', and is closed. */
    private void greet(ServerSocket server) {
        pool.submit(() -> {
            while (!server.isClosed()) {
                try (Socket accepted = server.accept()) {
                    accepted.getOutputStream().write('!');
                } catch (SocketTimeoutException idle) {
                    // keep accepting
                } catch (IOException closed) {
                    return null;
                }
            }
            return null;
        });
    }

    /** A connection through the WSS port reaches the (greeting) target: its byte comes back. */
    private static void assertForwarded(TestRobot source, int wssPort, String what) throws IOException {
        Socket socket;
        try {
            socket = source.connect(wssPort);
        } catch (ConnectException refused) {
            throw new AssertionError(what + ": WSS port " + wssPort + " refused the connection", refused);
        }
        try (socket) {
            int greeting;
            try {
                greeting = socket.getInputStream().read();
            } catch (SocketException reset) {
                greeting = -2;
            }
            assertEquals('!', greeting, what + ": the target's byte through WSS port " + wssPort
                    + " (-1: end of stream, -2: reset; the WSS closed the connection without forwarding it)");
        }
    }

    /** Connect, send a few bytes, read them at the target, close both ends. */
    private static void shortConnection(TestRobot source, int wssPort, ServerSocket targetAccepts, int i) throws IOException {
        byte[] data = ("#" + i).getBytes(StandardCharsets.UTF_8);
        try (Socket out = source.connect(wssPort)) {
            out.getOutputStream().write(data);
            try (Socket in = targetAccepts.accept()) {
                in.setSoTimeout(TestRobot.TIMEOUT_MS);
                assertArrayEquals(data, readExactlyBytes(in.getInputStream(), data.length), "connection " + i);
            }
        }
    }

    /** Records every event as its CSV line without the time field. */
    private static final class Recorder implements WssEventListener {
        private final List<String> events = new ArrayList<>();

        private synchronized void add(Object... fields) {
            events.add(Stream.of(fields).map(String::valueOf).collect(Collectors.joining(",")));
        }

        synchronized List<String> events() {
            return List.copyOf(events);
        }

        synchronized long count(String event) {
            return events.stream().filter(event::equals).count();
        }

        synchronized long sent(String from, String to) {
            String prefix = "DATA_SENT," + from + "," + to + ",";
            return events.stream().filter(e -> e.startsWith(prefix))
                    .mapToLong(e -> Long.parseLong(e.substring(prefix.length()))).sum();
        }

        @Override
        public void robotRegistered(String robot, String address, List<Integer> ports) {
            add("REGISTERED", robot, address, ports.stream().map(String::valueOf).collect(Collectors.joining(":")));
        }

        @Override
        public void robotDeregistered(String robot) {
            add("DEREGISTERED", robot);
        }

        @Override
        public void connectionEstablished(String from, String to, int targetPort) {
            add("CON_ESTABLISHED", from, to, targetPort);
        }

        @Override
        public void connectionTerminated(String from, String to, int targetPort) {
            add("CON_TERMINATED", from, to, targetPort);
        }

        @Override
        public void dataSent(String from, String to, int bytes) {
            add("DATA_SENT", from, to, bytes);
        }
    }
}
