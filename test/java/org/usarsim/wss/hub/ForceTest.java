package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.hub.Sockets.assertClosedByPeer;
import static org.usarsim.wss.hub.Sockets.readExactly;

import java.io.IOException;
import java.net.ConnectException;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;

/**
 * An operator's hand on the switch (issue 12): a pair forced down or up wins over the model, and
 * released it follows the model again. Real robots over loopback sockets, a {@link ScriptedModel}
 * as the model.
 */
class ForceTest {

    private static final RobotPair PAIR = RobotPair.of("R1", "R2");

    private final ScriptedModel model = new ScriptedModel();
    private final List<AutoCloseable> toClose = new ArrayList<>();
    private TestHub server;
    private Hub hub;
    private RobotLinkModel links;
    private TestRobot r1;
    private TestRobot r2;
    private ServerSocket r1Accepts;
    private ServerSocket r2Accepts;
    private int toR2;
    private int toR1;

    @TempDir
    Path dir;

    @BeforeEach
    void start() throws Exception {
        server = new TestHub(model, true, 65536);
        hub = server.hub;
        links = model.links();
        r1 = closing(server.robotAt("127.0.0.1"));
        r2 = closing(server.robotAt("127.0.0.2"));
        r1Accepts = r1.initAccepting("R1");
        r2Accepts = r2.initAccepting("R2");
        toR2 = r1.dns("R2", 0);
        toR1 = r2.dns("R1", 0);
    }

    @AfterEach
    void stop() {
        Sockets.closeAllNewestFirst(toClose);
        server.close();
    }

    private <T extends AutoCloseable> T closing(T closeable) {
        toClose.add(closeable);
        return closeable;
    }

    /** A connection R1 -> R2 through the WSS, accepted at R2. */
    private Socket[] connectR1ToR2() throws IOException {
        Socket out = closing(r1.connect(toR2));
        Socket in;
        try {
            in = closing(r2Accepts.accept());
        } catch (SocketTimeoutException e) {
            throw new AssertionError("R2 was not connected through WSS port " + toR2, e);
        }
        in.setSoTimeout(TestRobot.TIMEOUT_MS);
        return new Socket[] {out, in};
    }

    private static void assertPasses(Socket[] conn, String tag) throws IOException {
        byte[] there = (tag + ">").getBytes(StandardCharsets.UTF_8);
        conn[0].getOutputStream().write(there);
        assertEquals(tag + ">", readExactly(conn[1].getInputStream(), there.length), tag + ": R1 -> R2");
        byte[] back = ("<" + tag).getBytes(StandardCharsets.UTF_8);
        conn[1].getOutputStream().write(back);
        assertEquals("<" + tag, readExactly(conn[0].getInputStream(), back.length), tag + ": R2 -> R1");
    }

    private static void assertClosed(Socket[] conn, String what) throws IOException {
        assertClosedByPeer(conn[0], what + ": R1's end");
        assertClosedByPeer(conn[1], what + ": R2's end");
    }

    private static void assertRefused(TestRobot from, int wssPort, String what) {
        assertThrows(ConnectException.class, () -> from.connect(wssPort).close(), "WSS port " + wssPort + " refuses: " + what);
    }

    private boolean listening(int wssPort) {
        return hub.snapshot().ports().stream().filter(port -> port.wssPort() == wssPort).findFirst().orElseThrow().listening();
    }

    @Test
    void forcedDownClosesTheLinksAndRefusesConnectionsEvenInRangeUntilReleased() throws Exception {
        Socket[] conn = connectR1ToR2();
        assertPasses(conn, "before");

        hub.force("R2", "R1", Force.DOWN);
        assertEquals(Force.DOWN, hub.forced(PAIR), "a pair has no direction");
        assertClosed(conn, "forced down");
        assertRefused(r1, toR2, "R1 -> R2 forced down");
        assertRefused(r2, toR1, "R2 -> R1 forced down");
        assertEquals(toR2, r1.dns("R2", 0), "DNS still answers the pair's port, as for a broken pair");

        // The model says in range: resumes, allows. Forced down wins.
        links.resumeConnectionsForPair("R1", "R2");
        assertRefused(r1, toR2, "after the model's resume");
        assertEquals(toR2, r1.dns("R2", 0));
        assertRefused(r1, toR2, "after a DNS the model allows");

        // The robot leaves and comes back: still forced down.
        r2.control.close(); // its accepting socket stays open
        Wait.until("R2 left", () -> !links.getListOfRegisteredRobots().contains("R2"));
        TestRobot again = closing(server.robotAt("127.0.0.2"));
        again.init("R2", r2Accepts.getLocalPort());
        assertRefused(r1, toR2, "R2 came back");
        assertEquals(Force.DOWN, hub.forced(PAIR));

        hub.release("R1", "R2");
        assertNull(hub.forced(PAIR));
        assertTrue(listening(toR2), "released: the model allows the pair, so its port listens at once");
        assertPasses(connectR1ToR2(), "released");
    }

    @Test
    void forcedUpKeepsALinkTheModelBreaksAndAcceptsConnectionsTheModelForbids() throws Exception {
        Socket[] conn = connectR1ToR2();
        hub.force("R1", "R2", Force.UP);

        assertTrue(links.breakConnectionsForPair("R1", "R2"), "the model's verdict changed (its event is its own)");
        assertPasses(conn, "broken by the model, forced up");
        assertTrue(listening(toR2) && listening(toR1), "the ports listen through the model's break");
        assertPasses(connectR1ToR2(), "a new connection through the model's break");

        model.allowBoth("R1", "R2", false);
        assertPasses(connectR1ToR2(), "a connection the model forbids");
        assertEquals(toR1, r2.dns("R1", 0));

        // Forced up, but only while both robots are registered.
        r2.control.close();
        Wait.until("R2 left", () -> !links.getListOfRegisteredRobots().contains("R2"));
        assertRefused(r1, toR2, "R2 gone, though forced up");
        assertPasses(conn, "the established link lives on, as any link of a robot that left");
        TestRobot back = closing(server.robotAt("127.0.0.2"));
        back.init("R2", r2Accepts.getLocalPort());
        assertPasses(connectR1ToR2(), "R2 back: forced up again, though the model still forbids it");

        // Another pair, forced up, broken and forbidden by the model from the start of its link.
        TestRobot r2b = closing(server.robotAt("127.0.0.3"));
        ServerSocket r2bAccepts = r2b.initAccepting("R2b");
        int toR2b = r1.dns("R2b", 0);
        assertTrue(listening(toR2b), "R1 -> R2b is not forced: its own rules");
        hub.force("R1", "R2b", Force.UP);
        model.allowBoth("R1", "R2b", false);
        links.breakConnectionsForPair("R1", "R2b");
        try (Socket out = r1.connect(toR2b); Socket in = r2bAccepts.accept()) {
            out.getOutputStream().write('x');
            assertEquals('x', in.getInputStream().read(), "forwarded though broken and forbidden: forced up");
        }
    }

    @Test
    void releaseAppliesTheModelsBreakAtOnce() throws Exception {
        hub.force("R1", "R2", Force.UP);
        Socket[] conn = connectR1ToR2();
        links.breakConnectionsForPair("R1", "R2");
        assertPasses(conn, "forced up");

        hub.release("R1", "R2");
        assertClosed(conn, "released into the model's break");
        assertRefused(r1, toR2, "released, broken");
        assertRefused(r2, toR1, "released, broken");

        links.resumeConnectionsForPair("R1", "R2");
        assertPasses(connectR1ToR2(), "the model's next resume");
    }

    @Test
    void releaseAppliesWhatTheModelForbidsAtOnceAndItsNextPollAnyway() throws Exception {
        hub.force("R1", "R2", Force.UP);
        model.allowBoth("R1", "R2", false);
        Socket[] conn = connectR1ToR2();
        assertPasses(conn, "forbidden, forced up");

        hub.release("R1", "R2");
        assertClosed(conn, "released: the model forbids the pair");
        assertRefused(r1, toR2, "released, forbidden");

        // The model allows again: a DNS reopens as without any forcing; then its next poll breaks.
        model.allowBoth("R1", "R2", true);
        assertEquals(toR2, r1.dns("R2", 0));
        Socket[] again = connectR1ToR2();
        assertPasses(again, "allowed again");

        hub.force("R1", "R2", Force.DOWN);
        hub.release("R1", "R2");
        assertPasses(connectR1ToR2(), "released from down: the model allows");
        assertTrue(links.breakConnectionsForPair("R1", "R2"), "the model's next poll breaks the pair");
        assertRefused(r1, toR2, "the model's break after the release");
    }

    /**
     * An operator and the model change the pair at once, from two threads, many times; after
     * each round the pair's ports are as the last word of each says (forced beats the model),
     * in the hub's snapshot and on the wire: no state lost in a race.
     */
    @Test
    void theOperatorAndTheModelRacingLeaveThePairAsTheirLastWordsSay() throws Exception {
        ExecutorService threads = Executors.newFixedThreadPool(2);
        try {
            Random random = new Random(12);
            for (int round = 0; round < 20; round++) {
                int[] operatorOps = random.ints(200, 0, 3).toArray();
                int[] modelOps = random.ints(200, 0, 2).toArray();
                Future<?> operator = threads.submit(() -> {
                    for (int op : operatorOps) {
                        switch (op) {
                            case 0 -> hub.force("R1", "R2", Force.DOWN);
                            case 1 -> hub.force("R2", "R1", Force.UP);
                            default -> hub.release("R1", "R2");
                        }
                    }
                });
                Future<?> theModel = threads.submit(() -> {
                    for (int op : modelOps) {
                        if (op == 0) {
                            links.breakConnectionsForPair("R1", "R2");
                        } else {
                            links.resumeConnectionsForPair("R2", "R1");
                        }
                    }
                });
                operator.get(10, TimeUnit.SECONDS);
                theModel.get(10, TimeUnit.SECONDS);
                int lastForce = operatorOps[operatorOps.length - 1];
                boolean modelUp = modelOps[modelOps.length - 1] == 1;
                boolean talks = lastForce == 1 || (lastForce == 2 && modelUp);
                String state = "round " + round + ": operator " + List.of("down", "up", "released").get(lastForce)
                        + ", model " + (modelUp ? "resumed" : "broke");
                assertEquals(talks, listening(toR2) && listening(toR1), state);
                if (talks) {
                    assertPasses(connectR1ToR2(), state);
                } else {
                    assertRefused(r1, toR2, state);
                }
            }
        } finally {
            threads.shutdownNow();
        }
    }

    @Test
    void forcingAndReleasingAreWrittenToTheEventLogAndTheLog() throws Exception {
        CsvEventLog log = CsvEventLog.create(dir);
        hub.addListener(log);
        try (LogCapture info = LogCapture.of("org.usarsim.wss.events", Level.INFO)) {
            hub.force("R2", "R1", Force.DOWN);
            hub.force("R1", "R2", Force.DOWN); // no change: no event
            hub.force("R1", "R2", Force.UP);
            hub.release("R1", "R2");
            hub.release("R1", "R2"); // not forced: no event
            hub.force("Ahead", "Of-Time", Force.DOWN); // names not registered: allowed
            assertEquals(List.of("forced R1 - R2 down", "forced R1 - R2 up", "released R1 - R2 to the model",
                    "forced Ahead - Of-Time down"), info.messages(Level.INFO).stream()
                    .filter(m -> m.startsWith("forced") || m.startsWith("released")).toList());
        } finally {
            hub.removeListener(log);
            log.close();
        }
        List<String> lines = Files.readAllLines(log.file()).stream()
                .filter(line -> line.startsWith("FORCED") || line.startsWith("RELEASED"))
                .map(line -> line.replaceFirst(",\\d\\d:\\d\\d:\\d\\d\\.\\d{3}", "")).toList();
        assertEquals(List.of("FORCED,R1,R2,DOWN", "FORCED,R1,R2,UP", "RELEASED,R1,R2", "FORCED,Ahead,Of-Time,DOWN"), lines);
    }

    @Test
    void aPairIsTwoDifferentNames() {
        assertThrows(IllegalArgumentException.class, () -> hub.force("R1", "R1", Force.DOWN));
        assertThrows(IllegalArgumentException.class, () -> hub.force("", "R1", Force.UP));
        assertThrows(IllegalArgumentException.class, () -> hub.release("R1", "R1"));
    }

    @Test
    void pairsForcedInTheConfigurationAreForcedFromTheStart() throws Exception {
        HubConfig config = TestHub.config(true, 65536, 600, 1000, 30);
        config = new HubConfig(config.bindAddress(), 0, config.chunkSize(), config.socketBuffer(), true, 600, 1000,
                config.maxPortsPerAddress(), 30, Set.of(), Map.of(RobotPair.of("A", "B"), Force.DOWN, RobotPair.of("A", "C"), Force.UP),
                Map.of(), config.shaping(), config.fixed());
        ScriptedModel forbidding = new ScriptedModel();
        forbidding.allowBoth("A", "C", false);
        try (TestHub forced = new TestHub(forbidding, config); TestRobot a = forced.robot(); TestRobot b = forced.robot();
                TestRobot c = forced.robot()) {
            a.init("A");
            ServerSocket bAccepts = b.initAccepting("B");
            ServerSocket cAccepts = c.initAccepting("C");
            assertRefused(a, a.dns("B", 0), "A - B forced down from the start");
            try (Socket out = a.connect(a.dns("C", 0)); Socket in = cAccepts.accept()) {
                out.getOutputStream().write('c');
                assertEquals('c', in.getInputStream().read(), "A - C forced up from the start, though the model forbids it");
            }
            assertTrue(bAccepts.isBound());
        }
    }
}
