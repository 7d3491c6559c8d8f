package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * Routes in a real hub (docs/routes.md): ROUTE on the control port, from wss.operators only, as
 * FORCE; and the base's CUT_OFF and ROUTE lines in the CSV event log, once per change.
 */
class RouteCommandTest {

    @TempDir
    Path dir;

    private ScriptedModel model;
    private TestHub server;

    @BeforeEach
    void start() throws Exception {
        model = new ScriptedModel();
        server = new TestHub(model, true, 65536);
    }

    @AfterEach
    void stop() {
        server.close();
    }

    private void strength(String a, String b, double dBm) {
        model.strength(a, b, dBm);
        model.strength(b, a, dBm);
    }

    private void decide(Map<RobotPair, Boolean> states) {
        server.hub.robotLinks().applyLinkStates(states);
    }

    private static Map<RobotPair, Boolean> states(boolean r1r2, boolean r2r3, boolean r1r3) {
        Map<RobotPair, Boolean> states = new LinkedHashMap<>();
        states.put(RobotPair.of("R1", "R2"), r1r2);
        states.put(RobotPair.of("R2", "R3"), r2r3);
        states.put(RobotPair.of("R1", "R3"), r1r3);
        return states;
    }

    private static List<String> routeLines(CsvEventLog log) {
        try {
            return Files.readAllLines(log.file()).stream().filter(line -> line.startsWith("ROUTE,") || line.startsWith("CUT_OFF,"))
                    .map(line -> line.replaceFirst(",[\\d:.]+,", ",")).toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void pairsNoPollDecidedAreUpAsTheModelAllowsThemAsOnTheMap() throws Exception {
        // A model that decides no pair (the Noop model's way: every pair may talk) leaves robots reachable, not cut off.
        server.hub.setRouteBase("R1");
        try (TestRobot operator = server.robotAt("127.0.0.1"); TestRobot r1 = server.robot(); TestRobot r2 = server.robot();
                TestRobot r3 = server.robot()) {
            r1.init("R1", 5001);
            r2.init("R2", 5002);
            r3.init("R3", 5003);
            Wait.until("R3's direct route to R1", () -> server.hub.routes().route("R3", "R1").hops() == 1);
            assertEquals(List.of(), server.hub.routes().cutOff());
            assertEquals("ROUTEREPLY {Robot R3} {Peer R1} {Hops 1} {Path R3,R1} {Weakest R3,R1}",
                    operator.ask("ROUTE {Robot R3} {Peer R1}"));
            server.hub.force("R3", "R1", org.usarsim.wss.hub.core.Force.DOWN); // an operator's down counts, seen or not
            Wait.until("R3 to R1 through R2 once their pair is forced down", () -> server.hub.routes().route("R3", "R1").hops() == 2);
            model.allowBoth("R1", "R3", false);
            model.allowBoth("R2", "R3", false);
            server.hub.robotLinks().applyLinkStates(Map.of()); // a poll that decides nothing: the routes are found again
            Wait.until("R3 cut off once the model allows it no pair", () -> server.hub.routes().cutOff().equals(List.of("R3")));
        }
    }

    @Test
    void anOperatorAsksTheRouteOthersAreRefusedAsForFORCE() throws Exception {
        strength("R1", "R2", -50);
        strength("R2", "R3", -60);
        strength("R1", "R3", -90);
        try (TestRobot operator = server.robotAt("127.0.0.1"); TestRobot foreign = server.robotAt("127.0.0.2");
                TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); TestRobot r3 = server.robot()) {
            r1.init("R1", 5001);
            r2.init("R2", 5002);
            r3.init("R3", 5003);
            decide(states(true, true, false));
            Wait.until("R1's route to R3 through R2", () -> server.hub.routes().route("R1", "R3").hops() == 2);

            assertEquals("ROUTEREPLY {Robot R1} {Peer R3} {Hops 2} {Path R1,R2,R3} {Weakest R2,R3}",
                    operator.ask("ROUTE {Robot R1} {Peer R3}"), "unshaped: no rate");
            assertEquals("ROUTEREPLY {Robot R3} {Peer R2} {Hops 1} {Path R3,R2} {Weakest R3,R2}", operator.ask("ROUTE{Robot R3}{Peer R2}"));
            assertEquals("ROUTEREPLY {Robot R1} {Peer Nobody} {Hops -1}", operator.ask("ROUTE {Robot R1} {Peer Nobody}"));
            assertEquals("ERROR {Reason Not.An.Operator.Address}", foreign.ask("ROUTE {Robot R1} {Peer R3}"));
            foreign.init("R9", 5009);
            assertEquals("ERROR {Reason Not.An.Operator.Address}", foreign.ask("ROUTE {Robot R1} {Peer R3}"), "a robot is no operator");
        }
    }

    @Test
    void badROUTECommandsGetFORCEsReasons() throws Exception {
        try (TestRobot operator = server.robotAt("127.0.0.1")) {
            assertEquals("ERROR {Reason Robot.Name.Must.Not.Be.Empty}", operator.ask("ROUTE {Peer R2}"));
            assertEquals("ERROR {Reason Peer.Name.Must.Not.Be.Empty}", operator.ask("ROUTE {Robot R1}"));
            assertEquals("ERROR {Reason Peer.Name.Must.Not.Contain.Whitespace}", operator.ask("ROUTE {Robot R1} {Peer R 2}"));
            assertEquals("ERROR {Reason Peer.Must.Not.Be.The.Robot}", operator.ask("ROUTE {Robot R1} {Peer R1}"));
            assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", operator.ask("ROUTE"), "no segment, before INIT");
        }
    }

    @Test
    void theEventLogSaysEachChangeOfARobotsRouteToTheBaseOnce() throws Exception {
        CsvEventLog log = CsvEventLog.create(dir);
        server.hub.addListener(log);
        server.hub.setRouteBase("R3");
        strength("R1", "R2", -50);
        strength("R2", "R3", -60);
        strength("R1", "R3", -90);
        model.allowBoth("R1", "R2", false); // until the first poll decides them, the model allows no pair (as the map draws them)
        model.allowBoth("R2", "R3", false);
        model.allowBoth("R1", "R3", false);
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); TestRobot r3 = server.robot()) {
            r1.init("R1", 5001);
            r2.init("R2", 5002);
            r3.init("R3", 5003);
            Wait.until("R1 and R2 cut off: no pair up yet", () -> routeLines(log).size() == 2);
            decide(states(true, true, false));
            Wait.until("R1 routed", () -> routeLines(log).contains("ROUTE,R1,2,"));
            for (int poll = 0; poll < 5; poll++) {
                decide(states(true, true, false)); // polls that change nothing
            }
            decide(states(true, false, true)); // R2 - R3 broken: R2 goes by R1, R1 direct
            Wait.until("R2 rerouted", () -> routeLines(log).contains("ROUTE,R2,2,"));
            decide(states(true, false, true));
            decide(states(true, false, false)); // cut off
            Wait.until("R2 cut off again", () -> routeLines(log).stream().filter("CUT_OFF,R2"::equals).count() == 2);
            decide(states(true, false, false));
            decide(states(true, true, false)); // back
            try {
                Wait.until("R2 back", () -> routeLines(log).size() == 10);
            } catch (AssertionError e) {
                throw new AssertionError(routeLines(log).toString(), e);
            }
            assertEquals(List.of("CUT_OFF,R1", "CUT_OFF,R2", "ROUTE,R1,2,", "ROUTE,R2,1,", "ROUTE,R1,1,", "ROUTE,R2,2,", "CUT_OFF,R1", "CUT_OFF,R2",
                    "ROUTE,R1,2,", "ROUTE,R2,1,"), routeLines(log));
        } finally {
            log.close();
        }
    }

    @Test
    void withLinksShapedTheReplyHasTheRouteRateOverSharedAirtime() throws Exception {
        HubConfig shaped = TestHub.config(true, 65536, 600, 1000, 30)
                .withShaping(new ShapingConfig(true, RateTable.DEFAULT, 0, true), Map.of());
        try (TestHub other = new TestHub(new ScriptedModel(), shaped); TestRobot operator = other.robotAt("127.0.0.1")) {
            assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot A} {Peer B} {State Up} {Rate 24M}"));
            assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot B} {Peer C} {State Up} {Rate 12M}"));
            assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot A} {Peer C} {State Down}"));
            try (TestRobot a = other.robot(); TestRobot b = other.robot(); TestRobot c = other.robot()) {
                a.init("A", 5001);
                b.init("B", 5002);
                c.init("C", 5003);
                a.dns("B", 5002);
                b.dns("C", 5003);
                a.dns("C", 5003);
                Wait.until("A's route to C", () -> other.hub.routes().route("A", "C").rateBound() == 8_000_000);
                assertEquals("ROUTEREPLY {Robot A} {Peer C} {Hops 2} {Path A,B,C} {Weakest B,C} {Rate 8000000}",
                        operator.ask("ROUTE {Robot A} {Peer C}"), "24 and 12 Mbit/s through B's radio: 8");
                assertEquals("ROUTEREPLY {Robot A} {Peer Nobody} {Hops -1} {Rate 0}", operator.ask("ROUTE {Robot A} {Peer Nobody}"));
            }
        }
    }
}
