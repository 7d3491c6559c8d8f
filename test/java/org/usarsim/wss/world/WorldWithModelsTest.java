package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.hub.Sockets.assertClosedByPeer;

import java.net.InetAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.simulator.ModelRig;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;
import org.usarsim.wss.protocol.Replies;

/** The two simulator models against our world server, over real sockets, as a team would run them. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class WorldWithModelsTest {

    /** distance.n 3: a range of 55.6 m. */
    private static final PathLoss SHORT = new PathLoss(-49.67, 3, 2, -93);

    @TempDir
    Path dir;

    private WorldServer world;
    private ModelRig rig;

    private void start(String worldText, ModelRig.Factory factory) throws Exception {
        Path file = Files.writeString(dir.resolve("test.world"), worldText);
        world = WorldServer.start(file, InetAddress.getByName("127.0.0.1"), 0);
        rig = factory.create(world.port());
    }

    @AfterEach
    void stop() throws Exception {
        if (rig != null) {
            rig.close();
        }
        if (world != null) {
            world.close();
        }
    }

    @Test
    void distanceOnlyFollowsARobotDrivingOutOfRangeAndBack() throws Exception {
        // Runner goes from 10 m to 90 m and back at 50 m/s: out of range from 55.6 m, a lap in 3.2 s.
        start("""
                robot Base   0,0,0
                robot Runner 10,0,0
                path Runner speed 50 loop 90,0
                """, port -> ModelRig.polling(port, new DistanceOnlyPropagationModel(), Map.of("distance.n", "3")));
        TestRobot base = rig.robot("Base");
        rig.robot("Runner");
        int wssPort = base.dns("Runner", 0);
        Wait.until("Runner leaves range", () -> rig.events("OUT_OF_RANGE").size() >= 1);
        ModelRig.Event out = rig.events("OUT_OF_RANGE").get(0);
        assertEquals(List.of("Base", "Runner"), out.args().subList(0, 2));
        double distance = (double) out.args().get(3);
        assertTrue(distance > SHORT.range() && distance <= 90, "out of range at " + distance + " m");
        assertEquals(SHORT.strength(distance), (double) out.args().get(2), 1e-9);
        Wait.until("Runner comes back", () -> rig.events("IN_RANGE").size() >= 1);
        assertEquals(wssPort, base.dns("Runner", 0), "the same WSS port all along");
        assertEquals(List.of("Base", "Runner"), rig.server.hub.getListOfRegisteredRobots());
    }

    @Test
    void robotsWithAnEmptyBatteryOrNotInTheWorldAreKicked() throws Exception {
        start("""
                robot Base  0,0,0
                robot Tired 5,0,0 battery 1
                """, port -> ModelRig.polling(port, new DistanceOnlyPropagationModel(), Map.of()));
        rig.robot("Base");
        TestRobot tired = rig.robot("Tired");
        TestRobot ghost = rig.robot("Ghost");
        assertClosedByPeer(ghost.control, "Ghost, whom the world does not know");
        Wait.until("Tired's battery runs out", () -> rig.events("OUT_OF_BATTERY").size() == 1);
        assertClosedByPeer(tired.control, "Tired, out of battery");
        Wait.until("both are gone", () -> rig.events("DEREGISTERED").size() == 2);
        assertEquals(List.of("Base"), rig.server.hub.getListOfRegisteredRobots());
        assertEquals(List.of("DEREGISTERED[Ghost]", "OUT_OF_BATTERY[Tired]", "DEREGISTERED[Tired]"),
                rig.events("OUT_OF_BATTERY", "DEREGISTERED").stream().map(Object::toString).toList());
    }

    @Test
    void obstacleCountsComeFromTheWallsOfTheWorld() throws Exception {
        // Behind stands 30 m east of Base behind two walls; Open stands 30 m north with none between.
        start("""
                robot Base   0,0,0
                robot Behind 30,0,0
                robot Open   0,30,0
                wall 10,-5 10,5
                wall 20,-5 20,5
                """, port -> ModelRig.polling(port, new ObstaclePropagationModel(), Map.of("distance.n", "3")));
        TestRobot base = rig.robot("Base");
        rig.robot("Behind");
        rig.robot("Open");
        Wait.until("the counts are known", () -> rig.model.connectionIsPossibleForPair("Base", "Open")
                && !Double.isNaN(rig.model.getSignalStrengthForPair("Base", "Behind")));
        assertEquals(Replies.signal("Open", SHORT.strength(30)), base.ask("GETSS {Robot Open}"));
        assertEquals(Replies.signal("Behind", SHORT.strength(30) - 2 * 6.325), base.ask("GETSS {Robot Behind}"));
        assertTrue(SHORT.strength(30) - 2 * 6.325 < -93, "premise: two walls put Behind out of range");
        Wait.until("the pair behind the walls is broken", () -> !rig.model.connectionIsPossibleForPair("Base", "Behind"));
    }
}
