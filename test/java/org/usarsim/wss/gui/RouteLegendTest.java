package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.routes.Hop;
import org.usarsim.wss.routes.RouteFinder;
import org.usarsim.wss.routes.RouteGraph;
import org.usarsim.wss.routes.RouteRule;
import org.usarsim.wss.routes.RouteTable;

/** Issue 34, item 3: what the map's legend says of the routes, and which route a pick draws. */
class RouteLegendTest {

    /** Base - R1 - Scout up, shaped over shared airtime; Lost alone. */
    private static RouteTable table(String base) {
        List<Hop> hops = List.of(new Hop("Base", "R1", -70, 54_000_000), new Hop("R1", "Base", -70, 54_000_000),
                new Hop("R1", "Scout", -80, 24_000_000), new Hop("Scout", "R1", -80, 24_000_000));
        return RouteFinder.table(new RouteGraph(List.of("Base", "Lost", "R1", "Scout"), hops, RouteRule.FASTEST_SHARED_AIRTIME, base));
    }

    @Test
    void theLegendExplainsTheBaseAndTheCutOffRobotsWhenThereIsABaseAndTheBandWhileARouteIsDrawn() {
        assertEquals(List.of(), List.copyOf(MapSymbols.legend(RouteTable.EMPTY, false).keySet()));
        assertEquals(List.of("picked route"), List.copyOf(MapSymbols.legend(table(null), true).keySet()));
        assertEquals(List.of("base (Base)", "cut off from the base"), List.copyOf(MapSymbols.legend(table("Base"), false).keySet()));
        assertEquals(List.of("base (Base)", "cut off from the base", "picked route"),
                List.copyOf(MapSymbols.legend(table("Base"), true).keySet()));
    }

    @Test
    void aCompletePickDrawsItsRouteWithEachHopsRateThatWay() {
        MapData data = new MapData(List.of(), List.of(), List.of(), Double.NaN, table("Base"), List.of());
        assertNull(DrawnRoute.of(RoutePick.NONE, data));
        assertNull(DrawnRoute.of(new RoutePick("Base", null), data));
        DrawnRoute drawn = DrawnRoute.of(new RoutePick("Base", "Scout"), data);
        assertEquals(List.of("Base", "R1", "Scout"), drawn.route().path());
        assertEquals(List.of("54 Mbit/s", "24 Mbit/s"), drawn.hops().stream().map(hop -> RouteText.hopLabel(hop, drawn.shaped())).toList());
        assertTrue(drawn.shaped());
        DrawnRoute none = DrawnRoute.of(new RoutePick("Base", "Lost"), data);
        assertFalse(none.route().exists());
        assertEquals(List.of(), none.hops());
        assertTrue(data.routes().isCutOff("Lost"));
    }
}
