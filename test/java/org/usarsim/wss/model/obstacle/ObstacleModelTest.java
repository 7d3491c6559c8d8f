package org.usarsim.wss.model.obstacle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.hub.Sockets.assertClosedByPeer;

import java.net.ConnectException;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.simulator.DataConnection;
import org.usarsim.wss.model.simulator.FakeSimulator;
import org.usarsim.wss.model.simulator.ModelRig;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.protocol.Replies;

/** The Obstacle model for real: a fake simulator answering GETPOS and GETOBS, robots on a hub. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class ObstacleModelTest {

    private static final PathLoss DEFAULT = new PathLoss(-49.67, 1, 2, -93);

    private ModelRig rig;

    private ModelRig rig(Map<String, String> settings) throws Exception {
        rig = new ModelRig(new ObstaclePropagationModel(), settings);
        return rig;
    }

    @AfterEach
    void stop() throws Exception {
        if (rig != null) {
            rig.close();
        }
    }

    private long getobs(String line) {
        return rig.sim.getobsLines().stream().filter(line::equals).count();
    }

    @Test
    void eachObstacleTakesTheAttenuationOffTheDistanceStrength() throws Exception {
        rig(Map.of());
        TestRobot a = rig.robot("A", 0, 0, 0);
        rig.robot("B", 30, 40, 0);
        for (int walls = 0; walls <= 3; walls++) {
            rig.sim.obstacles("A", "B", walls);
            rig.sim.place("B", 30 + 2 * walls, 40, 0); // beyond the cache distance: asked again
            rig.polls(1);
            double expected = DEFAULT.strength(Math.hypot(30 + 2 * walls, 40)) - walls * 6.325;
            assertEquals(Replies.signal("B", expected), a.ask("GETSS {Robot B}"), walls + " walls");
            assertEquals(expected, rig.model.getSignalStrengthForPair("B", "A"), 1e-9);
        }
    }

    @Test
    void countsAreAskedInAscendingNameOrderAndCachedUntilARobotMovesBeyondTheCacheDistance() throws Exception {
        rig(Map.of("obstacle.cacheDistance", "1.0"));
        rig.sim.obstacles("Alpha", "Zulu", 1);
        rig.robot("Zulu", 0, 0, 0);
        rig.robot("Alpha", 10, 0, 0);
        rig.polls(5);
        String ask = "GETOBS {From Alpha} {To Zulu}";
        assertEquals(1, getobs(ask), "standing still: asked once " + rig.sim.getobsLines());
        rig.sim.place("Alpha", 10.9, 0, 0);
        rig.polls(3);
        assertEquals(1, getobs(ask), "0.9 m is within the cache distance");
        rig.sim.place("Zulu", 0, -1.5, 0);
        rig.polls(3);
        assertEquals(2, getobs(ask), "1.5 m is beyond it");
        assertEquals(List.of(ask, ask), rig.sim.getobsLines());
    }

    @Test
    void aRobotMovingBetweenPollsNeverHasNaNStrengthWhileItsCountIsAskedAgain() throws Exception {
        rig(Map.of());
        TestRobot a = rig.robot("A", 0, 0, 0);
        rig.robot("B", 10, 0, 0);
        rig.sim.obstacles("A", "B", 1);
        rig.polls(2);
        rig.sim.delayGetobs(60);
        ReportedRobot still = new ReportedRobot("A", 0, 0, 0, false);
        rig.sim.script(k -> List.of(still, new ReportedRobot("B", 10 + 2 * k, 0, 0, false)));
        long until = rig.sim.getposCount() + 8;
        int asked = 0;
        while (rig.sim.getposCount() < until) {
            String reply = a.ask("GETSS {Robot B}");
            assertFalse(reply.contains("NaN"), "after " + asked + " replies: " + reply);
            asked++;
        }
        assertTrue(rig.sim.getobsLines().size() >= 6, "B moved 2 m each poll: its count was asked again each time");
    }

    @Test
    void anUnknownCountMeansNaNAndNoConnection() throws Exception {
        rig(Map.of());
        TestRobot a = rig.robot("A", 0, 0, 0);
        rig.robot("B", 5, 0, 0); // the fake answers ObstCount -1.0000 for pairs it was not told about
        rig.polls(2);
        assertEquals("SS {Robot B} {Strength NaN} {Error Model.Returned.NaN}", a.ask("GETSS {Robot B}"));
        int port = a.dns("B", 0);
        assertThrows(ConnectException.class, () -> a.connect(port).close(), "the pair is broken");
        assertFalse(rig.model.connectionIsPossibleForPair("A", "B"));

        rig.sim.obstacles("A", "B", 0);
        rig.sim.place("B", 7, 0, 0);
        Wait.until("the pair connects once the count is known", () -> rig.model.connectionIsPossibleForPair("A", "B"));
        Wait.until("the port listens", () -> {
            try (Socket socket = a.connect(port)) {
                rig.accepts("B").accept().close();
                return true;
            } catch (ConnectException e) {
                return false;
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        });
    }

    @Test
    void aSimulatorThatDoesNotKnowGetobsLeavesPairsUnconnectedButKeepsThePositions() throws Exception {
        rig(Map.of());
        TestRobot a = rig.robot("A", 0, 0, 0);
        TestRobot b = rig.robot("B", 5, 0, 0);
        rig.sim.mode(FakeSimulator.Mode.NO_GETOBS);
        rig.sim.obstacles("A", "B", 0);
        rig.polls(3);
        assertFalse(rig.model.connectionIsPossibleForPair("A", "B"));
        assertEquals(List.of("A", "B"), rig.server.hub.getListOfRegisteredRobots());
        assertEquals(0, rig.logLines(Level.WARNING, "lost the simulator"), "GETPOS is still answered");
        assertEquals(1, rig.logLines(Level.WARNING, "the simulator answers no GETOBS"), "said once: " + rig.log.size() + " lines");
        rig.sim.remove("B");
        assertClosedByPeer(b.control, "B, no longer listed, is kicked");
        a.close();
    }

    @Test
    void wallsPutAPairOutOfRangeAndTakingThemAwayBringsItBack() throws Exception {
        // distance.n 3: 55.6 m in the open. Every move is 2 m, beyond the 1 m cache distance.
        rig(Map.of("distance.n", "3"));
        PathLoss open = new PathLoss(-49.67, 3, 2, -93);
        TestRobot a = rig.robot("A", 0, 0, 0);
        rig.robot("B", 18, 0, 0);
        rig.sim.obstacles("A", "B", 0);
        rig.polls(2);
        assertTrue(rig.model.connectionIsPossibleForPair("A", "B"));
        DataConnection conn = DataConnection.open(a, a.dns("B", 0), rig.accepts("B"));

        assertTrue(open.strength(20) - 2 * 6.325 >= -93, "premise: two walls at 20 m leave the pair in range");
        rig.sim.obstacles("A", "B", 2);
        rig.sim.place("B", 20, 0, 0);
        rig.polls(2);
        assertEquals(open.strength(20) - 2 * 6.325, rig.model.getSignalStrengthForPair("A", "B"), 1e-9);
        assertTrue(rig.model.connectionIsPossibleForPair("A", "B"));
        conn.assertPasses("through two walls");

        assertTrue(open.strength(18) - 3 * 6.325 < -93, "premise: three walls at 18 m put the pair out of range");
        rig.sim.obstacles("A", "B", 3);
        rig.sim.place("B", 18, 0, 0);
        assertClosedByPeer(conn.source(), "A's end once a third wall stands between");
        Wait.until("the event", () -> rig.events("OUT_OF_RANGE").size() == 1);
        List<ModelRig.Event> out = rig.events("OUT_OF_RANGE");
        assertEquals(1, out.size(), rig.events.toString());
        assertEquals(List.of("A", "B", open.strength(18) - 3 * 6.325, 18.0), out.get(0).args());

        rig.sim.obstacles("A", "B", 1);
        rig.sim.place("B", 20, 0, 0);
        Wait.until("the pair is back in range", () -> rig.events("IN_RANGE").size() == 1);
    }

    @Test
    void robotsAbsentFromANonEmptyListAreKickedButAnEmptyListKicksNobody() throws Exception {
        rig(Map.of());
        rig.robot("A", 0, 0, 0);
        TestRobot b = rig.robot("B", 5, 0, 0);
        rig.polls(1);
        rig.sim.remove("A");
        rig.sim.remove("B");
        rig.polls(3);
        assertEquals(List.of("A", "B"), rig.server.hub.getListOfRegisteredRobots(), "an empty list kicks nobody");
        rig.sim.place("A", 0, 0, 0);
        assertClosedByPeer(b.control, "B, absent from a non-empty list");
        Wait.until("B is deregistered", () -> rig.server.hub.getListOfRegisteredRobots().equals(List.of("A")));
    }

    @Test
    void theWallsOfAWorldFileAreCountedByTheModelAndDrawnWhateverTheSimulatorAnswers(@TempDir Path dir) throws Exception {
        Path world = Files.writeString(dir.resolve("walls.world"), "robot R 0,0,0\nwall 5,-10 5,10\nwall 7,-10 7,10\n");
        rig(Map.of("obstacle.walls", world.toString()));
        rig.sim.mode(FakeSimulator.Mode.NO_GETOBS);
        TestRobot a = rig.robot("A", 0, 0, 0);
        rig.robot("B", 10, 0, 0);
        rig.robot("C", 4, 3, 0);
        rig.polls(2);
        double oneWallLess = DEFAULT.strength(10) - 2 * 6.325;
        assertEquals(Replies.signal("B", oneWallLess), a.ask("GETSS {Robot B}"), "two walls between A and B");
        assertEquals(DEFAULT.strength(5), rig.model.getSignalStrengthForPair("A", "C"), 1e-9, "none between A and C");
        assertEquals(List.of(), rig.sim.getobsLines(), "the simulator is not asked");
        assertEquals(List.of(new Wall(5, -10, 5, 10), new Wall(7, -10, 7, 10)), rig.model.walls(), "the map shows them");
        assertEquals(1, rig.logLines(Level.INFO, "counting the obstacles between robots from the 2 walls of " + world));
    }

    @Test
    void aWallsFileThatCannotBeReadRefusesTheStart(@TempDir Path dir) throws Exception {
        Path world = Files.writeString(dir.resolve("bad.world"), "wall 5,-10\n");
        ObstaclePropagationModel model = new ObstaclePropagationModel();
        model.configure(new ModelSettings(Map.of("obstacle.walls", world.toString())));
        model.setRobotLinkModel(new RobotLinkModel() {
            @Override
            public boolean breakConnectionsForPair(String robotA, String robotB) {
                return false;
            }

            @Override
            public boolean resumeConnectionsForPair(String robotA, String robotB) {
                return false;
            }

            @Override
            public void kickOutRobot(String robot) {
            }

            @Override
            public List<String> getListOfRegisteredRobots() {
                return List.of();
            }
        });
        ModelStartException e = assertThrows(ModelStartException.class, model::start);
        assertTrue(e.getMessage().startsWith("obstacle.walls: " + world + ":1: "), e.getMessage());
        e = assertThrows(ModelStartException.class, () -> {
            model.configure(new ModelSettings(Map.of("obstacle.walls", dir.resolve("none.world").toString())));
            model.start();
        });
        assertEquals("obstacle.walls: " + dir.resolve("none.world") + ": no such file", e.getMessage());
    }
}
