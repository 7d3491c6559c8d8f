package org.usarsim.wss.routes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class RouteFinderTest {

    private static final long M = 1_000_000;

    /** Both ways of a pair, at one rate and strength. */
    private static List<Hop> pair(String a, String b, long rate, double dBm) {
        return List.of(new Hop(a, b, dBm, rate), new Hop(b, a, dBm, rate));
    }

    private static RouteTable table(RouteRule rule, List<String> robots, List<List<Hop>> pairs) {
        List<Hop> hops = new ArrayList<>();
        pairs.forEach(hops::addAll);
        return RouteFinder.table(new RouteGraph(robots, hops, rule, null));
    }

    @Test
    void aChainOfThreeHopsIsBoundByItsSlowestRelay() {
        RouteTable table = table(RouteRule.FASTEST_SHARED_AIRTIME, List.of("A", "B", "C", "D"),
                List.of(pair("A", "B", 24 * M, -50), pair("B", "C", 12 * M, -60), pair("C", "D", 24 * M, -55)));
        Route route = table.route("A", "D");
        assertEquals(List.of("A", "B", "C", "D"), route.path());
        assertEquals(3, route.hops());
        assertEquals(new Hop("B", "C", -60, 12 * M), route.weakest());
        assertEquals(8 * M, route.rateBound(), "24 and 12 through B: 24 x 12 / 36 Mbit/s");
        assertEquals(24 * M, table.route("A", "B").rateBound());
        assertEquals(8 * M, table.route("D", "A").rateBound());
    }

    @Test
    void aDiamondsFasterLongerRouteBeatsTheSlowDirectHop() {
        // A - D direct at 6; A - B - D at 24 and 24 (12 through B); A - C - D at 54 and 6 (5.4 through C).
        RouteTable table = table(RouteRule.FASTEST_SHARED_AIRTIME, List.of("A", "B", "C", "D"),
                List.of(pair("A", "D", 6 * M, -80), pair("A", "B", 24 * M, -60), pair("B", "D", 24 * M, -60),
                        pair("A", "C", 54 * M, -40), pair("C", "D", 6 * M, -80)));
        Route route = table.route("A", "D");
        assertEquals(List.of("A", "B", "D"), route.path());
        assertEquals(12 * M, route.rateBound());
        assertEquals("A,B,D", route.pathText());
    }

    @Test
    void anEqualRateGoesByTheFewestHops() {
        // Direct at 12; through B at 24 and 24: 12 too.
        RouteTable table = table(RouteRule.FASTEST_SHARED_AIRTIME, List.of("A", "B", "D"),
                List.of(pair("A", "D", 12 * M, -70), pair("A", "B", 24 * M, -60), pair("B", "D", 24 * M, -60)));
        assertEquals(List.of("A", "D"), table.route("A", "D").path());
        assertEquals(12 * M, table.route("A", "D").rateBound());
    }

    @Test
    void withoutSharedAirtimeTheSlowestHopBoundsTheRoute() {
        RouteTable table = table(RouteRule.FASTEST, List.of("A", "B", "D"),
                List.of(pair("A", "D", 12 * M, -70), pair("A", "B", 24 * M, -60), pair("B", "D", 24 * M, -60)));
        assertEquals(List.of("A", "B", "D"), table.route("A", "D").path());
        assertEquals(24 * M, table.route("A", "D").rateBound());
    }

    @Test
    void unshapedTheStrongestWeakestHopWinsThenTheFewestHops() {
        RouteTable table = table(RouteRule.STRONGEST, List.of("A", "B", "C", "D"),
                List.of(pair("A", "D", 0, -85), pair("A", "B", 0, -60), pair("B", "D", 0, -70),
                        pair("A", "C", 0, -70), pair("C", "B", 0, -50)));
        Route route = table.route("A", "D");
        assertEquals(List.of("A", "B", "D"), route.path(), "-70 at its weakest, in 2 hops (A,C,B,D is -70 in 3)");
        assertEquals(new Hop("B", "D", -70, 0), route.weakest());
        assertEquals(0, route.rateBound());
        assertFalse(table.rule().shaped());
    }

    @Test
    void aRobotOutOfReachHasNoRouteAndIsCutOffFromTheBase() {
        List<Hop> hops = new ArrayList<>(pair("A", "B", 0, -60));
        RouteTable table = RouteFinder.table(new RouteGraph(List.of("A", "B", "C"), hops, RouteRule.STRONGEST, "A"));
        Route none = table.route("C", "A");
        assertFalse(none.exists());
        assertEquals(-1, none.hops());
        assertNull(none.weakest());
        assertEquals(List.of("C"), table.cutOff());
        assertTrue(table.isCutOff("C"));
        assertFalse(table.isCutOff("A"), "the base is never cut off");
        assertEquals(1, table.toBase("B").hops());
    }

    @Test
    void aWayUpOnlyOneWayRoutesOnlyThatWay() {
        RouteTable table = RouteFinder.table(new RouteGraph(List.of("A", "B"), List.of(new Hop("A", "B", -50, 0)),
                RouteRule.STRONGEST, null));
        assertTrue(table.route("A", "B").exists());
        assertFalse(table.route("B", "A").exists());
    }

    @Test
    void anUnknownStrengthStillRoutesBelowEveryKnownOne() {
        RouteTable table = table(RouteRule.STRONGEST, List.of("A", "B", "C"),
                List.of(pair("A", "C", 0, Double.NaN), pair("A", "B", 0, -90), pair("B", "C", 0, -90)));
        assertEquals(List.of("A", "B", "C"), table.route("A", "C").path());
        RouteTable alone = table(RouteRule.STRONGEST, List.of("A", "C"), List.of(pair("A", "C", 0, Double.NaN)));
        assertEquals(1, alone.route("A", "C").hops());
    }

    @Test
    void theRelayBoundIsTheSharedAirtimeOfOneRadio() {
        assertEquals(500_000, RouteRule.relayBound(M, M));
        assertEquals(4 * M, RouteRule.relayBound(6 * M, 12 * M));
        assertEquals(0, RouteRule.relayBound(0, M));
        assertEquals(Long.MAX_VALUE / 2, RouteRule.relayBound(Long.MAX_VALUE, Long.MAX_VALUE), 1e12);
        List<Hop> three = List.of(new Hop("A", "B", 0, 6 * M), new Hop("B", "C", 0, 12 * M), new Hop("C", "D", 0, 12 * M));
        assertEquals(4 * M, RouteRule.FASTEST_SHARED_AIRTIME.bound(three));
        assertEquals(6 * M, RouteRule.FASTEST.bound(three));
        assertEquals(0, RouteRule.STRONGEST.bound(three));
    }

    @Test
    void theSameGraphGivesTheSameTable() {
        List<List<Hop>> pairs = List.of(pair("A", "B", 12 * M, -60), pair("B", "C", 12 * M, -60), pair("A", "C", 3 * M, -80));
        assertEquals(table(RouteRule.FASTEST_SHARED_AIRTIME, List.of("A", "B", "C"), pairs),
                table(RouteRule.FASTEST_SHARED_AIRTIME, List.of("C", "B", "A"), pairs));
    }

    /**
     * Small random graphs against every simple path: every route found is a simple path of hops
     * that are up, its bound its own, never better than the best; and the best, rank and hops,
     * for all but a few pairs (docs/routes.md, "Exactness": a route blocked by the robots a
     * better label had passed; 0.1 % of the pairs of these dense graphs).
     */
    @Test
    void itFindsWhatTryingEverySimplePathFindsForAllButAFewPairs() {
        Random random = new Random(34);
        long[] rates = {6 * M, 9 * M, 12 * M, 18 * M, 24 * M, 36 * M, 48 * M, 54 * M};
        int pairs = 0;
        int best = 0;
        for (int round = 0; round < 120; round++) {
            int n = 3 + random.nextInt(4);
            List<String> robots = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                robots.add("R" + i);
            }
            List<Hop> hops = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) {
                    if (i != j && random.nextDouble() < 0.6) {
                        hops.add(new Hop("R" + i, "R" + j, -40 - random.nextInt(50), rates[random.nextInt(rates.length)]));
                    }
                }
            }
            for (RouteRule rule : RouteRule.values()) {
                RouteTable table = RouteFinder.table(new RouteGraph(robots, hops, rule, null));
                for (String from : robots) {
                    for (String to : robots) {
                        if (!from.equals(to)) {
                            long[] expected = Exhaustive.best(rule, hops, from, to);
                            Route route = table.route(from, to);
                            String where = rule + " " + from + " -> " + to + ": " + route + " in " + hops;
                            assertEquals(expected[1] >= 0, route.exists(), where);
                            pairs++;
                            if (!route.exists()) {
                                best++;
                                continue;
                            }
                            List<Hop> path = Exhaustive.hopsOf(route.path(), hops);
                            assertEquals(path, route.legs(), where);
                            assertEquals(route.path().size(), route.path().stream().distinct().count(), where);
                            assertEquals(rule.bound(path), route.rateBound(), where);
                            assertTrue(rank(rule, route) <= expected[0], where);
                            if (rank(rule, route) == expected[0] && route.hops() == expected[1]) {
                                best++;
                            }
                        }
                    }
                }
            }
        }
        assertTrue(best >= pairs * 0.995, best + " of " + pairs);
    }

    /** Routes to the base come from one search from the base over the hops turned round: the same rank and hops as each robot's own. */
    @Test
    void aRouteToTheBaseRanksAsTheRobotsOwnSearchFindsIt() {
        Random random = new Random(7);
        long[] rates = {6 * M, 12 * M, 24 * M, 54 * M};
        for (int round = 0; round < 50; round++) {
            List<String> robots = List.of("B", "R1", "R2", "R3", "R4", "R5");
            List<Hop> hops = new ArrayList<>();
            for (String a : robots) {
                for (String b : robots) {
                    if (!a.equals(b) && random.nextDouble() < 0.5) {
                        hops.add(new Hop(a, b, -40 - random.nextInt(50), rates[random.nextInt(rates.length)]));
                    }
                }
            }
            RouteGraph graph = new RouteGraph(robots, hops, RouteRule.FASTEST_SHARED_AIRTIME, "B");
            RouteTable table = RouteFinder.table(graph);
            RouteFinder finder = new RouteFinder(graph);
            for (String robot : robots.subList(1, robots.size())) {
                Route own = finder.from(robot).stream().filter(route -> route.to().equals("B")).findFirst().orElse(Route.none(robot, "B"));
                Route toBase = table.toBase(robot);
                assertEquals(own.hops(), toBase.hops(), own + " / " + toBase);
                assertEquals(own.rateBound(), toBase.rateBound(), own + " / " + toBase);
                assertEquals(table.route(robot, "B"), toBase);
                if (toBase.exists()) {
                    assertEquals(Exhaustive.hopsOf(toBase.path(), hops), toBase.legs());
                    assertEquals(robot, toBase.from());
                }
            }
        }
    }

    private static long rank(RouteRule rule, Route route) {
        if (rule.shaped()) {
            return route.rateBound();
        }
        return (long) route.weakest().strength();
    }
}
