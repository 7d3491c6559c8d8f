package org.usarsim.wss.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.hub.MapLines.Line;
import org.usarsim.wss.monitor.Reading.RobotView;

/** What the events tell of a change (docs/monitor.md, "Timing"): structure at once, counts when due, each kind in one event. */
class StateDiffTest {

    private static RobotView robot(String name, double x) {
        return new RobotView(name, "127.0.0.1", List.of(5000), Double.NaN, new org.usarsim.wss.model.Position(x, 0, 0), 10, false);
    }

    private static PairEntry pair(PairState state, long bytes) {
        return new PairEntry("A", "B", state, -50, 3, bytes, 0, 0, 0, 1, 0, 0, 1, null);
    }

    private static Reading reading(List<RobotView> robots, List<PairEntry> pairs) {
        return new Reading(robots, List.of(), List.of(), pairs, List.of(new Line("A", "B", PairState.UP, -50, 0)), null, null,
                RoutesJson.EMPTY);
    }

    private static List<String> types(List<StateDiff.Change> changes) {
        return changes.stream().map(StateDiff.Change::type).toList();
    }

    @Test
    void aNewEntryAndAChangeOfStateAreToldAtOnceEachKindInOneEvent() {
        StateDiff diff = new StateDiff();
        List<StateDiff.Change> first = diff.step(reading(List.of(robot("A", 0), robot("B", 1)), List.of(pair(PairState.UP, 0))), false);
        assertEquals(List.of("robots", "pairs", "lines"), types(first));
        assertEquals(2, ((List<?>) first.get(0).data()).size());
        List<StateDiff.Change> forced = diff.step(reading(List.of(robot("A", 0), robot("B", 1)), List.of(pair(PairState.FORCED_DOWN, 0))), false);
        assertEquals(List.of("pairs"), types(forced));
        assertEquals("FORCED_DOWN", ((Map<?, ?>) ((List<?>) forced.get(0).data()).get(0)).get("state"));
    }

    @Test
    void countsOnlyWaitUntilTheyAreDueThenTheLatestIsTold() {
        StateDiff diff = new StateDiff();
        diff.step(reading(List.of(robot("A", 0)), List.of(pair(PairState.UP, 0))), true);
        assertEquals(List.of(), types(diff.step(reading(List.of(robot("A", 5)), List.of(pair(PairState.UP, 100))), false)));
        assertEquals(0L, diff.sent().pairs().get(0).bytesFirstToSecond(), "the snapshot shows what was told");
        List<StateDiff.Change> due = diff.step(reading(List.of(robot("A", 6)), List.of(pair(PairState.UP, 200))), true);
        assertEquals(List.of("robots", "pairs"), types(due));
        assertEquals(200L, ((Map<?, ?>) ((List<?>) due.get(1).data()).get(0)).get("bytesFirstToSecond"));
    }

    @Test
    void whatIsGoneIsOneRemovedEvent() {
        StateDiff diff = new StateDiff();
        diff.step(reading(List.of(robot("A", 0), robot("B", 1)), List.of()), false);
        List<StateDiff.Change> gone = diff.step(new Reading(List.of(robot("A", 0)), List.of(), List.of(), List.of(), List.of(), null, null,
                RoutesJson.EMPTY), false);
        assertEquals(List.of("removed"), types(gone));
        assertEquals(Map.of("robots", List.of("B"), "lines", List.of(Map.of("first", "A", "second", "B"))), gone.get(0).data());
    }

    private static Reading withRoutes(RoutesJson routes) {
        return new Reading(List.of(), List.of(), List.of(), List.of(), List.of(), null, null, routes);
    }

    private static RoutesJson routes(boolean up) {
        List<org.usarsim.wss.routes.Hop> hops = up ? List.of(new org.usarsim.wss.routes.Hop("A", "B", -50, 0),
                new org.usarsim.wss.routes.Hop("B", "A", -50, 0)) : List.of();
        return RoutesJson.of(org.usarsim.wss.routes.RouteFinder.table(
                new org.usarsim.wss.routes.RouteGraph(List.of("A", "B"), hops, org.usarsim.wss.routes.RouteRule.STRONGEST, "B")));
    }

    @Test
    void theRoutesAreOneWholeEventWhenTheirTableChangedAndNoneForAnEqualOne() {
        StateDiff diff = new StateDiff();
        diff.reset(withRoutes(routes(false)));
        assertEquals(List.of(), types(diff.step(withRoutes(routes(false)), true)), "an equal table made again");
        List<StateDiff.Change> changes = diff.step(withRoutes(routes(true)), false);
        assertEquals(List.of("routes"), types(changes), "at once, not only when counts are due");
        Map<?, ?> data = (Map<?, ?>) changes.get(0).data();
        assertEquals("B", data.get("base"));
        assertEquals(List.of(), data.get("cutOff"));
        assertEquals(2, ((List<?>) data.get("routes")).size());
        assertEquals(List.of("A"), ((Map<?, ?>) diff.step(withRoutes(routes(false)), false).get(0).data()).get("cutOff"));
    }

    /** A chain A - B - C - D - E, both ways at {@code strengths}[i] between robots i and i + 1 (null: no pair), base A. */
    private static RoutesJson chain(Double... strengths) {
        List<String> robots = List.of("A", "B", "C", "D", "E");
        List<org.usarsim.wss.routes.Hop> hops = new java.util.ArrayList<>();
        for (int i = 0; i < strengths.length; i++) {
            if (strengths[i] != null) {
                hops.add(new org.usarsim.wss.routes.Hop(robots.get(i), robots.get(i + 1), strengths[i], 0));
                hops.add(new org.usarsim.wss.routes.Hop(robots.get(i + 1), robots.get(i), strengths[i], 0));
            }
        }
        return RoutesJson.of(org.usarsim.wss.routes.RouteFinder.table(
                new org.usarsim.wss.routes.RouteGraph(robots, hops, org.usarsim.wss.routes.RouteRule.STRONGEST, "A")));
    }

    @Test
    void aChangeOfSomeRoutesIsToldAsThoseRoutesAndThoseGone() {
        StateDiff diff = new StateDiff();
        diff.reset(withRoutes(chain(-50.0, -50.0, -50.0, -50.0)));
        assertEquals(List.of(), types(diff.step(withRoutes(chain(-50.0, -50.0, -50.0, -60.0)), false)),
                "no robot cut off or back: the routes wait for the counts");
        List<StateDiff.Change> weaker = diff.step(withRoutes(chain(-50.0, -50.0, -50.0, -60.0)), true);
        assertEquals(List.of("routeChanges"), types(weaker));
        Map<?, ?> data = (Map<?, ?>) weaker.get(0).data();
        assertEquals(8, ((List<?>) data.get("routes")).size(), "the 8 routes over D - E, not all 20");
        for (Object route : (List<?>) data.get("routes")) {
            assertTrue(((List<?>) ((Map<?, ?>) route).get("path")).containsAll(List.of("D", "E")), route.toString());
        }
        assertEquals(List.of(), data.get("gone"));
        assertEquals(List.of(), data.get("cutOff"));

        List<StateDiff.Change> cut = diff.step(withRoutes(chain(-50.0, -50.0, -50.0, null)), false);
        assertEquals(List.of("routeChanges"), types(cut), "E cut off: at once");
        data = (Map<?, ?>) cut.get(0).data();
        assertEquals(List.of(), data.get("routes"));
        assertEquals(8, ((List<?>) data.get("gone")).size(), "every route to or from E");
        assertEquals(List.of("E"), data.get("cutOff"));

        List<StateDiff.Change> most = diff.step(withRoutes(chain(-50.0, null, -50.0, -50.0)), true);
        assertEquals(List.of("routes"), types(most), "more than half the routes changed: the whole, shorter");
        assertEquals(List.of(), types(diff.step(withRoutes(chain(-50.0, null, -50.0, -50.0)), true)), "an equal table");
    }
}
