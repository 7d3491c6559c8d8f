package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;

/** What the map asks a simulator model: positions, ranges, the cutoff and the walls (GETWALLS), over real sockets. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
@Tag("slow")
class MapFactsTest {

    private ModelRig rig;

    @AfterEach
    void close() throws Exception {
        if (rig != null) {
            rig.close();
        }
    }

    /** DistanceOnly polling a fake that answers GETWALLS with {@code reply} from its first connection on; A at (0, 0, 0). */
    private static ModelRig answeringGetwalls(String reply) throws Exception {
        FakeSimulator fake = new FakeSimulator();
        fake.answerGetwalls(reply);
        ModelRig rig = ModelRig.with(fake, new DistanceOnlyPropagationModel(), Map.of());
        rig.robot("A", 0, 0, 0);
        return rig;
    }

    @Test
    void positionsAreTheLastPollsAndTheRangeIsWhereTheStrengthReachesTheCutoff() throws Exception {
        rig = new ModelRig(new DistanceOnlyPropagationModel(), Map.of("distance.n", "3"));
        rig.robot("A", 1.5, -2, 0.25);
        rig.robot("B", 10, 0, 0);
        rig.polls(1);
        assertEquals(Optional.of(new Position(1.5, -2, 0.25)), rig.model.positionOf("A"));
        assertEquals(Optional.empty(), rig.model.positionOf("nobody"));
        // 2 * 10^((-49.67 + 93) / 30) = 55.6 m, and the strength there is the cutoff.
        double range = rig.model.rangeFor("A", "B");
        assertEquals(55.63, range, 0.01);
        assertEquals(-93, new PathLoss(-49.67, 3, 2, -93).strength(range), 1e-9);
        assertEquals(-93, rig.model.cutoff());
        rig.sim.place("B", 30, 40, 0);
        rig.polls(1);
        assertEquals(Optional.of(new Position(30, 40, 0)), rig.model.positionOf("B"), "the map follows every poll");
    }

    @Test
    void aSimulatorThatIgnoresGetwallsHasNoWallsSaidOnceAndPollsGoOn() throws Exception {
        rig = new ModelRig(new DistanceOnlyPropagationModel(), Map.of());
        rig.robot("A", 0, 0, 0);
        rig.polls(3);
        assertEquals(List.of(), rig.model.walls());
        assertEquals(1, rig.logLines(Level.INFO, "gives no walls"));
        assertEquals(0, rig.logLines(Level.WARNING, "lost the simulator"));
        assertTrue(rig.model.positionOf("A").isPresent());
        // Another connection asks again; still said once in the run.
        rig.sim.dropClients();
        rig.polls(3);
        assertEquals(1, rig.logLines(Level.INFO, "gives no walls"));
    }

    @Test
    void anUnknownCommandAnswerToGetwallsMeansNoWallsNotALostSimulator() throws Exception {
        rig = answeringGetwalls("ERROR {Reason unknown command GETWALLS}");
        rig.polls(3);
        assertEquals(List.of(), rig.model.walls());
        assertEquals(1, rig.logLines(Level.INFO, "gives no walls"));
        assertEquals(0, rig.logLines(Level.WARNING, "lost the simulator"));
        assertTrue(rig.model.positionOf("A").isPresent());
    }

    @Test
    void wallsGivenAreTakenAndABadListCostsOnlyTheWalls() throws Exception {
        rig = answeringGetwalls("WALLS {Walls 2} {Wall 0,0,10,0} {Wall -1.5,2.25,-1.5,8}");
        rig.polls(2);
        assertEquals(List.of(new Wall(0, 0, 10, 0), new Wall(-1.5, 2.25, -1.5, 8)), rig.model.walls());
        assertEquals(1, rig.logLines(Level.INFO, "gives 2 walls"));

        rig.sim.answerGetwalls("WALLS {Walls 1} {Wall 0,0,ten,0}");
        rig.sim.dropClients();
        // The new connection's walls are gone before its bad list is read and said: wait for the saying.
        Wait.until("the new connection's bad list said", () -> rig.logLines(Level.WARNING, "cannot be read") == 1);
        assertEquals(List.of(), rig.model.walls());
        assertTrue(rig.model.positionOf("A").isPresent());
    }

    @Test
    void aWallsLineOverTheLineLimitCostsOnlyTheWalls() throws Exception {
        // A world of some 30 000 walls (a floor plan converted by a tool): its WALLS line is over 1 MiB.
        StringBuilder walls = new StringBuilder("WALLS {Walls 30000}");
        for (int i = 0; i < 30_000; i++) {
            walls.append(" {Wall ").append(i).append(".1234,-1.5000,").append(i + 1).append(".5678,-1.5000}");
        }
        assertTrue(walls.length() > UsarsimSource.MAX_LINE_BYTES);
        rig = answeringGetwalls(walls.toString());
        rig.polls(3);
        assertEquals(0, rig.logLines(Level.WARNING, "lost the simulator"), "the positions still come");
        assertTrue(rig.model.positionOf("A").isPresent());
        assertEquals(List.of(), rig.model.walls());
        assertEquals(1, rig.logLines(Level.WARNING, "cannot be read"));
    }

    @Test
    void theObstacleRangeIsThePairsWithItsWallsAndTheOpenSpaceOneForARobotAlone() throws Exception {
        rig = new ModelRig(new ObstaclePropagationModel(), Map.of("distance.n", "3"));
        rig.robot("A", 0, 0, 0);
        rig.robot("B", 10, 0, 0);
        rig.sim.obstacles("A", "B", 2);
        rig.polls(2);
        // Two walls of 6.325 dB: 2 * 10^((-49.67 - 12.65 + 93) / 30) = 21.0 m.
        assertEquals(2 * Math.pow(10, (-49.67 - 2 * 6.325 + 93) / 30), rig.model.rangeFor("A", "B"), 1e-9);
        assertEquals(55.63, rig.model.rangeFor("A", "A"), 0.01);
    }
}
