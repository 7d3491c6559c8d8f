package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.routes.Hop;
import org.usarsim.wss.routes.Route;

/** Issue 34, item 3: how the map's status line, a hop's label and the Routes table say a route. */
class RouteTextTest {

    private static final Hop WEAK = new Hop("R1", "R2", -82.04, 6_000_000);
    private static final Route THREE = new Route("Alpha", "Scout", List.of("Alpha", "R1", "R2", "Scout"),
            List.of(new Hop("Alpha", "R1", -70, 24_000_000), WEAK, new Hop("R2", "Scout", -75, 18_000_000)), WEAK, 1_200_000);

    @Test
    void theStatusLineSaysHowThenTheStartThenTheRoute() {
        assertEquals(RouteText.HOW, RouteText.status(RoutePick.NONE, null, true));
        assertEquals("Route from Alpha: click another robot (a click on Alpha or Escape clears)",
                RouteText.status(new RoutePick("Alpha", null), null, true));
        RoutePick both = new RoutePick("Alpha", "Scout");
        assertEquals("Alpha -> Scout: 3 hops via R1, R2, bound 1.2 Mbit/s; weakest hop R1 -> R2 at 6 Mbit/s",
                RouteText.status(both, THREE, true));
        Route unshaped = new Route("Alpha", "Scout", THREE.path(), List.of(), new Hop("R1", "R2", -82.04, 0), 0);
        assertEquals("Alpha -> Scout: 3 hops via R1, R2; weakest hop R1 -> R2 at -82.0 dBm", RouteText.status(both, unshaped, false));
        Route direct = new Route("Alpha", "Scout", List.of("Alpha", "Scout"), List.of(new Hop("Alpha", "Scout", -60, 54_000_000)),
                new Hop("Alpha", "Scout", -60, 54_000_000), 54_000_000);
        assertEquals("Alpha -> Scout: 1 hop, direct, bound 54 Mbit/s; weakest hop Alpha -> Scout at 54 Mbit/s",
                RouteText.status(both, direct, true));
        assertEquals("Alpha -> Scout: no route (no chain of links up joins them)", RouteText.status(both, Route.none("Alpha", "Scout"), true));
    }

    @Test
    void aHopIsLabelledWithItsRateWithLinksShapedItsStrengthWithout() {
        assertEquals("6 Mbit/s", RouteText.hopLabel(WEAK, true));
        assertEquals("-82.0 dBm", RouteText.hopLabel(WEAK, false));
        assertEquals("", RouteText.hopLabel(new Hop("A", "B", Double.NaN, 0), false), "no strength known: no label");
        assertEquals("1.5 Mbit/s", RouteText.hopLabel(new Hop("A", "B", -70, 1_500_000), true));
    }

    @Test
    void theTableSaysThePathAndTheWeakestHop() {
        assertEquals("Alpha > R1 > R2 > Scout", RouteText.path(THREE));
        assertEquals("no route", RouteText.path(Route.none("Alpha", "Scout")));
        assertEquals("R1 > R2, -82.0 dBm, 6 Mbit/s", RouteText.weakest(WEAK));
        assertEquals("R1 > R2, -82.0 dBm", RouteText.weakest(new Hop("R1", "R2", -82.04, 0)));
        assertEquals("", RouteText.weakest(null));
    }
}
