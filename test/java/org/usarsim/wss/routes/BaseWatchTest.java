package org.usarsim.wss.routes;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class BaseWatchTest {

    private static final long M = 1_000_000;

    /** A, B and the base S: A - S at {@code direct} (0: down), A - B at 24M, B - S at {@code viaB} (0: down). */
    private static RouteTable table(String base, long direct, long viaB, String... robots) {
        List<Hop> hops = new ArrayList<>();
        add(hops, "A", "S", direct);
        add(hops, "A", "B", 24 * M);
        add(hops, "B", "S", viaB);
        return RouteFinder.table(new RouteGraph(List.of(robots.length == 0 ? new String[] {"A", "B", "S"} : robots), hops,
                RouteRule.FASTEST_SHARED_AIRTIME, base));
    }

    private static void add(List<Hop> hops, String a, String b, long rate) {
        if (rate > 0) {
            hops.add(new Hop(a, b, -60, rate));
            hops.add(new Hop(b, a, -60, rate));
        }
    }

    private static List<String> said(List<BaseWatch.Change> changes) {
        return changes.stream().map(c -> c.cutOff() ? "CUT_OFF " + c.robot()
                : "ROUTE " + c.robot() + " " + c.route().pathText() + " " + c.route().rateBound()).toList();
    }

    @Test
    void eachRobotIsSaidOnceThenAtEachChangeOnly() {
        BaseWatch watch = new BaseWatch();
        assertEquals(List.of("ROUTE A A,S 12000000", "ROUTE B B,S 12000000"), said(watch.next(table("S", 12 * M, 12 * M))));
        assertEquals(List.of(), said(watch.next(table("S", 12 * M, 12 * M))), "the same table: nothing");
        assertEquals(List.of(), said(watch.next(table("S", 11 * M, 12 * M))), "A's rate down by less than 10 %: not said");
        assertEquals(List.of("ROUTE A A,S 10000000"), said(watch.next(table("S", 10 * M, 12 * M))), "by 10 % of the last said");
        assertEquals(List.of("ROUTE A A,B,S 8000000"), said(watch.next(table("S", 0, 12 * M))), "another path");
        assertEquals(List.of("CUT_OFF A", "CUT_OFF B"), said(watch.next(table("S", 0, 0))));
        assertEquals(List.of(), said(watch.next(table("S", 0, 0))));
        assertEquals(List.of("ROUTE B B,S 12000000"), said(watch.next(table("S", 0, 12 * M, "B", "S"))), "A left: not said");
        assertEquals(List.of("ROUTE A A,B,S 8000000"), said(watch.next(table("S", 0, 12 * M))), "A back: said again");
    }

    @Test
    void noBaseSaysNothingAndANewBaseSaysEveryRobotAgain() {
        BaseWatch watch = new BaseWatch();
        assertEquals(List.of(), watch.next(table(null, 12 * M, 12 * M)));
        assertEquals(List.of("ROUTE A A,S 12000000", "ROUTE B B,S 12000000"), said(watch.next(table("S", 12 * M, 12 * M))));
        assertEquals(List.of("ROUTE A A,B 24000000", "ROUTE S S,B 12000000"), said(watch.next(table("B", 12 * M, 12 * M))));
        assertEquals(List.of("CUT_OFF A", "CUT_OFF B", "CUT_OFF S"), said(watch.next(table("Gone", 12 * M, 12 * M))),
                "a base that is not here: everyone cut off");
    }
}
