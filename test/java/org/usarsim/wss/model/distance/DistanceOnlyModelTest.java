package org.usarsim.wss.model.distance;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.hub.Sockets.assertClosedByPeer;
import static org.usarsim.wss.hub.Sockets.readExactly;

import java.io.IOException;
import java.net.ConnectException;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.simulator.DataConnection;
import org.usarsim.wss.model.simulator.FakeSimulator;
import org.usarsim.wss.model.simulator.ManualClock;
import org.usarsim.wss.model.simulator.ModelRig;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.protocol.Replies;

/**
 * The DistanceOnly model for real: a fake simulator on loopback, the model polling it every 100 ms,
 * robots on a hub talking the text protocol and forwarding data.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class DistanceOnlyModelTest {

    private static final Pattern STRENGTH = Pattern.compile("SS \\{Robot B\\} \\{Strength (\\S+)\\}");
    /** distance.n 3: range = 2 * 10^(43.33 / 30) = 55.6 m. */
    private static final Map<String, String> SHORT_RANGE = Map.of("distance.n", "3");

    private ModelRig rig;

    private ModelRig rig(Map<String, String> settings) throws Exception {
        rig = new ModelRig(new DistanceOnlyPropagationModel(), settings);
        return rig;
    }

    @AfterEach
    void stop() throws Exception {
        if (rig != null) {
            rig.close();
        }
    }

    // ---- strength ----

    @Test
    void strengthsMatchTheFormulaToFourDecimals() throws Exception {
        rig(Map.of());
        PathLoss loss = new PathLoss(-49.67, 1, 2, -93);
        TestRobot a = rig.robot("A", 1, 2, 0.5);
        rig.robot("B", 1, 2, 0.5);
        double[][] places = {{4, 6, 0.5}, {13.5, 2, 0.5}, {1, 2, 100.5}, {-1233.5, 2, 0.5}, {700, -300, 12.25}, {3.1, 2.2, 0.7}};
        for (double[] place : places) {
            rig.sim.place("B", place[0], place[1], place[2]);
            rig.polls(1);
            double distance = Math.sqrt(Math.pow(place[0] - 1, 2) + Math.pow(place[1] - 2, 2) + Math.pow(place[2] - 0.5, 2));
            double expected = loss.strength(distance);
            String reply = a.ask("GETSS {Robot B}");
            assertEquals(Replies.signal("B", expected), reply, "at " + distance + " m");
            Matcher matcher = STRENGTH.matcher(reply);
            assertTrue(matcher.matches(), reply);
            assertEquals(expected, Double.parseDouble(matcher.group(1)), 0.5e-4, "the wire value at " + distance + " m");
            assertEquals(expected, rig.model.getSignalStrengthForPair("A", "B"), 1e-9);
        }
    }

    @Test
    void coLocatedRobotsGiveInf() throws Exception {
        rig(Map.of());
        TestRobot a = rig.robot("A", 5, 5, 0);
        rig.robot("B", 5, 5, 0);
        rig.polls(1);
        assertEquals("SS {Robot B} {Strength INF} {Error Model.Returned.INF}", a.ask("GETSS {Robot B}"));
        assertTrue(rig.model.connectionIsPossibleForPair("A", "B"));
    }

    @Test
    void aRobotWithNoKnownPositionHasNaNAndMayConnect() throws Exception {
        rig(Map.of());
        rig.sim.mode(FakeSimulator.Mode.SILENT);
        TestRobot a = rig.server.robot();
        TestRobot b = rig.server.robot();
        a.initAccepting("A");
        ServerSocket bAccepts = b.initAccepting("B");
        assertEquals("SS {Robot B} {Strength NaN} {Error Model.Returned.NaN}", a.ask("GETSS {Robot B}"));
        DataConnection conn = DataConnection.open(a, a.dns("B", 0), bAccepts);
        conn.assertPasses("with unknown positions");
        conn.close();
        a.close();
        b.close();
    }

    // ---- range ----

    @Test
    void aPairOutOfRangeLosesItsConnectionsAndPortThenBackInRangeTheSamePortListens() throws Exception {
        ManualClock clock = new ManualClock();
        rig = new ModelRig(new DistanceOnlyPropagationModel(clock), Map.of("distance.n", "3", "usarsim.interval", "200"), clock);
        TestRobot a = rig.robot("A", 0, 0, 0);
        rig.robot("B", 10, 0, 0);
        ServerSocket bAccepts = rig.accepts("B");
        rig.polls(1);
        int port = a.dns("B", 0);
        DataConnection conn = DataConnection.open(a, port, bAccepts);
        conn.assertPasses("in range");

        rig.sim.place("B", 100, 0, 0);
        assertEquals(TimeUnit.MILLISECONDS.toNanos(200), clock.wakePoller(), "the next poll, one 200 ms interval after the last");
        // The poller sleeps until the test moves the clock again: that one poll did all this.
        assertClosedByPeer(conn.source(), "A's end");
        assertClosedByPeer(conn.target(), "B's end");
        TestRobot source = a;
        Wait.until("the WSS port refuses", () -> refuses(source, port));
        assertEquals(port, a.dns("B", 0), "the number is kept while out of range");
        assertEquals(Replies.signal("B", new PathLoss(-49.67, 3, 2, -93).strength(100)), a.ask("GETSS {Robot B}"));

        Wait.until("the event", () -> rig.events("OUT_OF_RANGE").size() == 1);
        List<ModelRig.Event> out = rig.events("OUT_OF_RANGE");
        assertEquals(1, out.size(), rig.events.toString());
        assertEquals(List.of("A", "B", new PathLoss(-49.67, 3, 2, -93).strength(100), 100.0), out.get(0).args());

        rig.sim.place("B", 20, 0, 0);
        rig.polls(1);
        DataConnection[] again = new DataConnection[1];
        Wait.until("the same WSS port listens again", () -> (again[0] = openIfListening(source, port, bAccepts)) != null);
        assertEquals(port, a.dns("B", 0));
        again[0].assertPasses("back in range");
        Wait.until("the event", () -> rig.events("IN_RANGE").size() == 1);
        assertEquals(List.of("IN_RANGE[A, B]"), rig.events("IN_RANGE").stream().map(Object::toString).toList());
        again[0].close();
        conn.close();
    }

    /** A connection through the port, or null while it refuses. */
    private static DataConnection openIfListening(TestRobot robot, int port, ServerSocket targetAccepts) {
        try {
            return DataConnection.open(robot, port, targetAccepts);
        } catch (ConnectException e) {
            return null;
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static boolean refuses(TestRobot robot, int port) {
        try (Socket socket = robot.connect(port)) {
            // Accepted: a port that does not listen any more refuses, it does not accept and close.
            return false;
        } catch (ConnectException e) {
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    // ---- kicks ----

    @Test
    void aRobotTheSimulatorDoesNotListIsKicked() throws Exception {
        rig(Map.of());
        rig.robot("A", 0, 0, 0);
        TestRobot b = rig.robot("B", 1, 0, 0);
        rig.polls(1);
        rig.sim.remove("B");
        assertClosedByPeer(b.control, "B's control connection");
        Wait.until("B is deregistered", () -> rig.events("DEREGISTERED").size() == 1);
        assertEquals(List.of("A"), rig.server.hub.getListOfRegisteredRobots());
        assertEquals(List.of("DEREGISTERED[B]"), rig.events("DEREGISTERED", "OUT_OF_BATTERY").stream().map(Object::toString).toList());
        assertEquals(1, rig.logLines(Level.INFO, "kicking B: the simulator does not list it"));
    }

    @Test
    void aRobotWhoseBatteryIsEmptyIsReportedThenKicked() throws Exception {
        rig(Map.of());
        rig.robot("A", 0, 0, 0);
        TestRobot b = rig.robot("B", 1, 0, 0);
        rig.polls(1);
        rig.sim.emptyBattery("B");
        assertClosedByPeer(b.control, "B's control connection");
        Wait.until("B is deregistered", () -> rig.events("DEREGISTERED").size() == 1);
        assertEquals(List.of("OUT_OF_BATTERY[B]", "DEREGISTERED[B]"),
                rig.events("DEREGISTERED", "OUT_OF_BATTERY").stream().map(Object::toString).toList());
        assertEquals(List.of("A"), rig.server.hub.getListOfRegisteredRobots());
    }

    // ---- the simulator misbehaving ----

    @Test
    void aSilentSimulatorIsReportedOnceTheLastStateKeptAndItsReturnNoticed() throws Exception {
        rig(SHORT_RANGE);
        TestRobot a = rig.robot("A", 0, 0, 0);
        rig.robot("B", 10, 0, 0);
        rig.polls(1);
        ServerSocket bAccepts = rig.accepts("B");
        DataConnection conn = DataConnection.open(a, a.dns("B", 0), bAccepts);
        String before = a.ask("GETSS {Robot B}");

        rig.sim.mode(FakeSimulator.Mode.SILENT);
        rig.sim.place("B", 500, 0, 0);
        long connections = rig.sim.connectionCount();
        Wait.until("the model reconnected twice", () -> rig.sim.connectionCount() >= connections + 2);
        // Still serving, with the last known state: the strength, the link, the data.
        assertEquals(before, a.ask("GETSS {Robot B}"));
        conn.assertPasses("while the simulator is silent");
        assertEquals(List.of("A", "B"), rig.server.hub.getListOfRegisteredRobots());
        assertEquals(1, rig.logLines(Level.WARNING, "lost the simulator at 127.0.0.1:" + rig.sim.port()), rig.log.toString());
        assertEquals(1, rig.logLines(Level.WARNING, "no answer to GETPOS within 300 ms"));

        rig.sim.mode(FakeSimulator.Mode.ANSWER);
        Wait.until("the model says the simulator is back", () -> rig.logLines(Level.INFO, "answers again") == 1);
        assertClosedByPeer(conn.source(), "A's end once B's move is known");
        assertEquals(1, rig.logLines(Level.WARNING, "lost the simulator"));
    }

    @Test
    void aSimulatorThatGoesAwayIsReconnectedWhileRobotsKeepBeingServed() throws Exception {
        rig(SHORT_RANGE);
        TestRobot a = rig.robot("A", 0, 0, 0);
        rig.robot("B", 10, 0, 0);
        rig.polls(1);
        String before = a.ask("GETSS {Robot B}");

        rig.sim.stopListening();
        Wait.until("the model noticed", () -> rig.logLines(Level.WARNING, "lost the simulator") == 1);
        for (int i = 0; i < 5; i++) {
            assertEquals(before, a.ask("GETSS {Robot B}"), "a reply while the simulator is away");
        }
        assertEquals(List.of("A", "B"), rig.server.hub.getListOfRegisteredRobots());

        rig.sim.place("B", 20, 0, 0);
        rig.sim.listenAgain();
        Wait.until("the model says the simulator is back", () -> rig.logLines(Level.INFO, "answers again") == 1);
        rig.polls(1);
        assertEquals(Replies.signal("B", new PathLoss(-49.67, 3, 2, -93).strength(20)), a.ask("GETSS {Robot B}"));
        assertEquals(1, rig.logLines(Level.WARNING, "lost the simulator"));
    }

    @Test
    void garbageFromTheSimulatorIsReportedOnceAndTheLastStateKept() throws Exception {
        rig(SHORT_RANGE);
        TestRobot a = rig.robot("A", 0, 0, 0);
        rig.robot("B", 10, 0, 0);
        rig.polls(1);
        String before = a.ask("GETSS {Robot B}");

        rig.sim.mode(FakeSimulator.Mode.GARBAGE);
        long connections = rig.sim.connectionCount();
        Wait.until("the model reconnected twice", () -> rig.sim.connectionCount() >= connections + 2);
        assertEquals(before, a.ask("GETSS {Robot B}"));
        assertEquals(List.of("A", "B"), rig.server.hub.getListOfRegisteredRobots());
        assertEquals(1, rig.logLines(Level.WARNING, "unexpected reply: this is not a reply"), rig.log.toString());

        rig.sim.mode(FakeSimulator.Mode.ANSWER);
        Wait.until("the model says the simulator is back", () -> rig.logLines(Level.INFO, "answers again") == 1);
    }

    @Test
    void anUnreachableSimulatorStopsTheStartWithItsHostAndPort() throws Exception {
        int free;
        try (ServerSocket probe = new ServerSocket(0, 1, java.net.InetAddress.getByName("127.0.0.1"))) {
            free = probe.getLocalPort();
        }
        DistanceOnlyPropagationModel model = new DistanceOnlyPropagationModel();
        model.configure(new ModelSettings(Map.of("usarsim.host", "127.0.0.1", "usarsim.port", Integer.toString(free))));
        ModelStartException e = assertThrows(ModelStartException.class, () -> new TestHub(model, true, 65536).close());
        assertTrue(e.getMessage().startsWith("cannot reach the simulator at 127.0.0.1:" + free + " ("), e.getMessage());
        assertFalse(model.isActive());
    }

    @Test
    void theSimulatorMayBeNamedByHostName() throws Exception {
        rig(Map.of("usarsim.host", "localhost"));
        rig.robot("A", 0, 0, 0);
        rig.polls(2);
        assertTrue(rig.model.isActive());
        assertEquals(List.of("A"), rig.server.hub.getListOfRegisteredRobots());
    }

    // ---- flapping at the edge ----

    /** Strength cutoff + 1 dB and cutoff - 1 dB for the defaults (N 1): 34 196 m and 43 052 m ... */
    private static double at(double strength) {
        return 2 * Math.pow(10, (-49.67 - strength) / 10);
    }

    /** After the pair is up at cutoff + 1 dB, B oscillates between cutoff - 1 dB and cutoff + 1 dB at every poll. */
    private List<ModelRig.Event> oscillate(int polls) throws Exception {
        rig.robot("A", 0, 0, 0);
        rig.robot("B", at(-92), 0, 0);
        rig.polls(2);
        rig.events.clear();
        ReportedRobot a = new ReportedRobot("A", 0, 0, 0, false);
        rig.sim.script(k -> List.of(a, new ReportedRobot("B", at(k % 2 == 1 ? -94 : -92), 0, 0, false)));
        rig.polls(polls);
        return rig.events("OUT_OF_RANGE", "IN_RANGE");
    }

    @Test
    void byDefaultALinkAtTheEdgeFlapsAtEveryPollLikeTheOriginal() throws Exception {
        rig(Map.of());
        List<ModelRig.Event> changes = oscillate(8);
        assertTrue(changes.size() >= 8, changes.toString());
        for (int i = 0; i < changes.size(); i++) {
            assertEquals(i % 2 == 0 ? "OUT_OF_RANGE" : "IN_RANGE", changes.get(i).type(), changes.toString());
        }
    }

    @Test
    void aMarginKeepsABrokenLinkDownUntilTheStrengthClearsIt() throws Exception {
        rig(Map.of("distance.margin", "3"));
        List<ModelRig.Event> changes = oscillate(8);
        assertEquals(List.of("OUT_OF_RANGE"), changes.stream().map(ModelRig.Event::type).toList(), "one break, no flapping");
        rig.sim.script(k -> List.of(new ReportedRobot("A", 0, 0, 0, false), new ReportedRobot("B", at(-89.5), 0, 0, false)));
        Wait.until("the link comes back above cutoff + margin", () -> rig.events("IN_RANGE").size() == 1);
    }

    @Test
    void aHoldTimeKeepsEachLinkStateAtLeastThatLong() throws Exception {
        ManualClock clock = new ManualClock();
        rig = new ModelRig(new DistanceOnlyPropagationModel(clock), Map.of("distance.holdTime", "0.4"), clock);
        long started = clock.nanoTime();
        List<ModelRig.Event> changes = oscillate(14);
        long tookMs = TimeUnit.NANOSECONDS.toMillis(clock.nanoTime() - started);
        assertTrue(changes.size() >= 2, "14 polls at the edge change the link more than once: " + changes);
        assertTrue(changes.size() <= tookMs / 400 + 1, "at most one change per 0.4 s over " + tookMs + " ms: " + changes);
        for (int i = 1; i < changes.size(); i++) {
            long gapMs = TimeUnit.NANOSECONDS.toMillis(changes.get(i).nanos() - changes.get(i - 1).nanos());
            assertTrue(gapMs >= 400, "changes " + gapMs + " ms apart: " + changes);
        }
    }

    @Test
    void aLongHoldTimeKeepsANewLinkUpThroughTheFlapping() throws Exception {
        rig(Map.of("distance.holdTime", "30"));
        assertEquals(List.of(), oscillate(8));
    }

    // ---- helpers ----
}
