package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.RobotPair;

/** One poll's decisions with positions, counts and times given: no socket, no clock, no hub. */
class PollStepTest {

    private static final long SECOND = 1_000_000_000L;
    private static final PathLoss PATH_LOSS = new PathLoss(-49.67, 3, 2, -93);
    /** The DistanceOnly strength less 10 dB per obstacle, as the Obstacle model with attenuation 10. */
    private static final PollStep.Strength STRENGTH = (a, b, obstacles) ->
            PATH_LOSS.strength(a.distanceTo(b)) - (Double.isNaN(obstacles) ? 0 : obstacles * 10);

    private static ReportedRobot at(String name, double x) {
        return new ReportedRobot(name, x, 0, 0, false);
    }

    private static Map<String, ReportedRobot> listed(ReportedRobot... robots) {
        java.util.Map<String, ReportedRobot> map = new java.util.LinkedHashMap<>();
        for (ReportedRobot robot : robots) {
            map.put(robot.name(), robot);
        }
        return map;
    }

    private static List<String> states(PollStep.Decision decision) {
        return decision.links().stream().map(link -> link.pair() + (link.live() ? " up" : " down")).toList();
    }

    @Test
    void robotsTheSimulatorDoesNotListOrWhoseBatteryIsEmptyAreKickedWithTheirReason() {
        Map<String, ReportedRobot> listed = listed(at("A", 0), new ReportedRobot("B", 1, 0, 0, true));
        List<PollStep.Kick> kicks = PollStep.kicks(List.of("A", "B", "C"), listed, true);
        assertEquals(List.of(new PollStep.Kick("B", true), new PollStep.Kick("C", false)), kicks);
        assertEquals(List.of("its battery is empty", "the simulator does not list it"),
                kicks.stream().map(kick -> kick.reason("simulator")).toList());
        assertEquals(List.of(new PollStep.Kick("B", true)), PollStep.kicks(List.of("A", "B", "C"), listed, false),
                "absent robots stay when the model does not kick them; an empty battery is kicked all the same");
    }

    @Test
    void thePairsDecidedAreThoseOfRegisteredRobotsListedWithBatteryLeft() {
        Map<String, ReportedRobot> listed = listed(at("A", 0), at("B", 10), new ReportedRobot("C", 1, 0, 0, true), at("X", 5));
        List<String> present = PollStep.present(List.of("A", "B", "C", "D"), listed);
        assertEquals(List.of("A", "B"), present, "X is listed but not registered, C is out of battery, D unlisted");
        assertEquals(List.of(RobotPair.of("A", "B")), PollStep.pairs(present));
        assertEquals(List.of(RobotPair.of("A", "B"), RobotPair.of("A", "C"), RobotPair.of("B", "C")),
                PollStep.pairs(List.of("A", "B", "C")));
    }

    @Test
    void eachPairIsDecidedOnItsStrengthAndDistance() {
        LinkStates none = new LinkStates(-93, 0, 0);
        PollStep.Decision decision = PollStep.decide(List.of("A", "B", "C"), listed(at("A", 0), at("B", 10), at("C", 100)),
                Map.of(), 0, none, STRENGTH);
        assertEquals(List.of("A <-> B up", "A <-> C down", "B <-> C down"), states(decision));
        PollStep.Link ac = decision.links().get(1);
        assertEquals(PATH_LOSS.strength(100), ac.strength());
        assertEquals(100.0, ac.distance());
    }

    @Test
    void obstaclesTakeTheirAttenuationOffThePairTheyAreCountedFor() {
        Map<String, ReportedRobot> listed = listed(at("A", 0), at("B", 10), at("C", 10));
        PollStep.Decision decision = PollStep.decide(List.of("A", "B", "C"), listed, Map.of(RobotPair.of("B", "A"), 2.0), 0,
                new LinkStates(-93, 0, 0), STRENGTH);
        assertEquals(PATH_LOSS.strength(10) - 20, decision.links().get(0).strength());
        assertEquals(PATH_LOSS.strength(10), decision.links().get(1).strength(), "A and C: none counted");
    }

    /** B at the edge: cutoff + 1 dB at even polls, cutoff - 1 dB at odd ones, one poll every 100 ms. */
    private static List<String> oscillate(LinkStates start, int polls) {
        double up = 2 * Math.pow(10, (-49.67 + 92) / 30);
        double down = 2 * Math.pow(10, (-49.67 + 94) / 30);
        LinkStates states = start;
        List<String> changes = new java.util.ArrayList<>();
        Boolean last = null;
        for (int k = 0; k < polls; k++) {
            long now = k * SECOND / 10;
            PollStep.Decision decision = PollStep.decide(List.of("A", "B"), listed(at("A", 0), at("B", k % 2 == 0 ? up : down)),
                    Map.of(), now, states, STRENGTH);
            boolean live = decision.links().get(0).live();
            if (last != null && live != last) {
                changes.add((live ? "up at " : "down at ") + now / (SECOND / 10) * 100 + " ms");
            }
            last = live;
            states = decision.snapshot().links();
        }
        return changes;
    }

    @Test
    void withoutMarginOrHoldALinkAtTheEdgeFlapsAtEveryPollLikeTheOriginal() {
        assertEquals(List.of("down at 100 ms", "up at 200 ms", "down at 300 ms", "up at 400 ms", "down at 500 ms"),
                oscillate(new LinkStates(-93, 0, 0), 6));
    }

    @Test
    void aMarginKeepsABrokenLinkDownThroughTheFlapping() {
        assertEquals(List.of("down at 100 ms"), oscillate(new LinkStates(-93, 3, 0), 10), "one break, no flapping");
    }

    @Test
    void aHoldTimeKeepsEachLinkStateAtLeastThatLong() {
        assertEquals(List.of("down at 500 ms", "up at 1000 ms", "down at 1500 ms"), oscillate(new LinkStates(-93, 0, 0.4), 16),
                "16 polls at the edge: a change at most every 0.4 s, at the first poll it is allowed");
        assertEquals(List.of(), oscillate(new LinkStates(-93, 0, 30), 8), "a long hold time keeps a new link up");
    }

    @Test
    void pairsOfRobotsNoLongerPresentAreForgotten() {
        PollStep.Decision first = PollStep.decide(List.of("A", "B"), listed(at("A", 0), at("B", 10)), Map.of(), 0,
                new LinkStates(-93, 0, 0), STRENGTH);
        PollStep.Decision second = PollStep.decide(List.of("A"), listed(at("A", 0), at("B", 10)), Map.of(), 1,
                first.snapshot().links(), STRENGTH);
        assertEquals(List.of(), second.links());
        assertNull(second.snapshot().links().live(RobotPair.of("A", "B")), "B left: its pairs start afresh when it returns");
    }

    @Test
    void aSnapshotHoldsOnePollsPositionsCountsAndStatesAndNoLaterPollChangesIt() {
        Map<String, ReportedRobot> before = listed(at("A", 0), at("B", 10));
        PollStep.Decision first = PollStep.decide(List.of("A", "B"), before, Map.of(RobotPair.of("A", "B"), 0.0), 5,
                new LinkStates(-93, 0, 0), STRENGTH);
        PollSnapshot published = first.snapshot();

        // The next poll: B moved behind six obstacles. Decided while a GETSS still reads the first snapshot.
        PollStep.Decision second = PollStep.decide(List.of("A", "B"), listed(at("A", 0), at("B", 12)),
                Map.of(RobotPair.of("A", "B"), 6.0), 6, published.links(), STRENGTH);

        assertEquals(before, published.positions());
        assertEquals(0.0, published.obstacles(RobotPair.of("B", "A")), "the first poll's count, with the first poll's positions");
        assertEquals(Boolean.TRUE, published.links().live(RobotPair.of("A", "B")));
        assertEquals(5, published.nanos());
        PollSnapshot next = second.snapshot();
        assertEquals(12.0, next.positions().get("B").x());
        assertEquals(6.0, next.obstacles(RobotPair.of("A", "B")));
        assertEquals(Boolean.FALSE, next.links().live(RobotPair.of("A", "B")), "-49.67 - 30 log10(6) - 60 dBm: down");
        assertEquals(Double.NaN, next.obstacles(RobotPair.of("A", "C")), "a pair not counted");
    }
}
