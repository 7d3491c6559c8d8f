package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
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
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;

/** What both simulator models share: a poll that fails, a stop and a new start, a reply cut by a timeout. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class SimulatorModelTest {

    /** DistanceOnly whose strength throws while told to: a bug in a model, not the simulator's fault. */
    static final class Faulty extends SimulatorModel {
        volatile boolean fail;

        @Override
        protected double strength(ReportedRobot a, ReportedRobot b, double obstacles) {
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
    void aLostSimulatorIsRetriedAfterPausesThatDoubleUpToTenSecondsThenPollingResumesAtTheInterval() throws Exception {
        ManualClock clock = new ManualClock();
        rig = new ModelRig(new DistanceOnlyPropagationModel(clock), Map.of(), clock);
        rig.robot("A", 0, 0, 0);
        rig.polls(1);
        rig.sim.stopListening();
        int before = clock.pauses().size();
        for (int i = 0; i < 9; i++) {
            clock.wakePoller();
        }
        assertEquals(List.of(100L, 200L, 400L, 800L, 1600L, 3200L, 6400L, 10000L, 10000L),
                clock.pauses().subList(before, before + 9).stream().map(TimeUnit.NANOSECONDS::toMillis).toList(),
                "after each failed attempt; the interval is 100 ms");
        assertEquals(1, rig.logLines(Level.WARNING, "lost the simulator"));

        rig.sim.listenAgain();
        clock.wakePoller();
        assertEquals(1, rig.logLines(Level.INFO, "the simulator at 127.0.0.1:" + rig.sim.port() + " answers again after 32 s"),
                rig.log.toString());
        assertEquals(100L, TimeUnit.NANOSECONDS.toMillis(clock.pauses().get(clock.pauses().size() - 1)), "the interval again");
        assertEquals(List.of("A"), rig.server.hub.getListOfRegisteredRobots(), "robots are kept while the simulator is away");
    }

    @Test
    void theConfigurationIsCheckedByTheDeclaredRulesAndFrozenAtStart() throws Exception {
        SimulatorConfig defaults = SimulatorConfig.read(SimulatorSettings.ALL, Map.of());
        assertEquals(new PathLoss(-49.67, 1, 2, -93), defaults.pathLoss(), "the declared defaults");
        assertEquals("127.0.0.1:7435", defaults.where());
        assertEquals(1000, defaults.intervalMs());
        ModelStartException refused = assertThrows(ModelStartException.class,
                () -> SimulatorConfig.read(SimulatorSettings.ALL, Map.of("usarsim.port", "0")));
        assertEquals("usarsim.port: '0' is not a port number from 1 to 65535", refused.getMessage());
        refused = assertThrows(ModelStartException.class,
                () -> SimulatorConfig.read(SimulatorSettings.ALL, Map.of("distance.n", "0")));
        assertEquals("distance.n: '0' is not a number above 0", refused.getMessage());

        rig = new ModelRig(new DistanceOnlyPropagationModel(), Map.of("distance.n", "3"));
        rig.robot("A", 0, 0, 0);
        rig.robot("B", 10, 0, 0);
        rig.polls(1);
        rig.model.configure(new ModelSettings(Map.of("distance.n", "1")));
        rig.polls(2);
        assertEquals(new PathLoss(-49.67, 3, 2, -93).strength(10), rig.model.getSignalStrengthForPair("A", "B"),
                "a running model keeps the configuration it started with");
    }

    @Test
    void aReplyCutByATimeoutIsWholeWhenItsEndComes() throws Exception {
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"));
                UsarsimSource connection = UsarsimSource.open("127.0.0.1", server.getLocalPort(), 200);
                Socket simulator = server.accept()) {
            OutputStream out = simulator.getOutputStream();
            out.write("NUMOBS {From A} {To B} {Obs".getBytes(StandardCharsets.US_ASCII));
            assertEquals(Map.of(), connection.obstacles(List.of(RobotPair.of("A", "B"))), "no whole answer within 200 ms");
            out.write("tCount 1.0000}\r\nPOSITIONS {Robots 1} {Name A Location 1,2,3 BatteryEmpty False}\r\n"
                    .getBytes(StandardCharsets.US_ASCII));
            assertEquals(Map.of("A", new ReportedRobot("A", 1, 2, 3, false)), connection.positions(List.of()),
                    "the late NUMOBS is skipped whole, not read as garbage");
        }
    }
}
