package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.hub.Wait;

/** What both simulator models share: a poll that fails, a stop and a new start, a reply cut by a timeout. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class SimulatorModelTest {

    /** DistanceOnly whose strength throws while told to: a bug in a model, not the simulator's fault. */
    static final class Faulty extends SimulatorModel {
        volatile boolean fail;

        @Override
        protected double strength(ReportedRobot a, ReportedRobot b) {
            if (fail) {
                throw new IllegalStateException("a bug in the model");
            }
            return pathLoss().strength(a.distanceTo(b));
        }

        @Override
        protected boolean allowsUnknownRobots() {
            return true;
        }

        @Override
        protected boolean kicksRobotsAbsentFrom(Map<String, ReportedRobot> listed) {
            return true;
        }
    }

    private ModelRig rig;

    @AfterEach
    void stop() throws Exception {
        if (rig != null) {
            rig.close();
        }
    }

    private static long pollerThreads() {
        return Thread.getAllStackTraces().keySet().stream().filter(t -> t.getName().endsWith(" poller") && t.isAlive()).count();
    }

    @Test
    void aPollThatFailsIsLoggedOnceAndPollingGoesOn() throws Exception {
        Faulty model = new Faulty();
        rig = new ModelRig(model, Map.of("distance.n", "3"));
        rig.robot("A", 0, 0, 0);
        rig.robot("B", 10, 0, 0);
        rig.polls(1);
        model.fail = true;
        rig.polls(5);
        assertEquals(1, rig.logLines(Level.WARNING, "a poll failed (java.lang.IllegalStateException: a bug in the model)"));
        assertTrue(model.isActive());
        model.fail = false;
        rig.sim.place("B", 100, 0, 0);
        Wait.until("polls decide again", () -> rig.events("OUT_OF_RANGE").size() == 1);
    }

    @Test
    void aStoppedModelStartsAgainWithOnePoller() throws Exception {
        long before = pollerThreads();
        rig = new ModelRig(new DistanceOnlyPropagationModel(), Map.of());
        rig.robot("A", 0, 0, 0);
        rig.polls(1);
        // Stopped in the middle of a poll that waits for an answer that never comes.
        rig.sim.mode(FakeSimulator.Mode.SILENT);
        long asked = rig.sim.getposCount();
        Wait.until("a GETPOS waits for its answer", () -> rig.sim.getposCount() > asked);
        rig.model.shutdown();
        assertFalse(rig.model.isActive());
        assertEquals(before, pollerThreads(), "the poller ended with the shutdown");

        rig.sim.mode(FakeSimulator.Mode.ANSWER);
        rig.model.start();
        assertTrue(rig.model.isActive());
        rig.polls(3);
        assertEquals(before + 1, pollerThreads());
        assertEquals(0, rig.logLines(Level.WARNING, "lost the simulator"), "a stop is not a lost simulator");
        rig.sim.remove("A");
        Wait.until("the new run kicks", () -> rig.events("DEREGISTERED").size() == 1);
    }

    @Test
    void aReplyCutByATimeoutIsWholeWhenItsEndComes() throws Exception {
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"));
                SimulatorConnection connection = SimulatorConnection.open("127.0.0.1", server.getLocalPort(), 200);
                Socket simulator = server.accept()) {
            OutputStream out = simulator.getOutputStream();
            out.write("NUMOBS {From A} {To B} {Obs".getBytes(StandardCharsets.US_ASCII));
            assertEquals(Map.of(), connection.obstacles(List.of(RobotPair.of("A", "B"))), "no whole answer within 200 ms");
            out.write("tCount 1.0000}\r\nPOSITIONS {Robots 1} {Name A Location 1,2,3 BatteryEmpty False}\r\n"
                    .getBytes(StandardCharsets.US_ASCII));
            assertEquals(Map.of("A", new ReportedRobot("A", 1, 2, 3, false)), connection.positions(),
                    "the late NUMOBS is skipped whole, not read as garbage");
        }
    }
}
