package org.usarsim.wss.gui;

import java.util.List;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.routes.RouteTable;

/**
 * "Routes": a row per ordered pair of registered robots, its best route now (docs/routes.md): From,
 * To, Hops (empty when there is none), Route (the robots in order, or "no route"), Weakest hop
 * (its pair, strength and with links shaped rate) and Rate bound (with links shaped, the rate
 * one stream could have over the whole route; {@link RateCell}). Filtered as the other tables, by
 * "From To"; rows replaced only when the route table changed. A route longer than its column is
 * cut, its whole text the cell's tooltip ({@link SidewaysTable}).
 */
final class RoutesPanel extends FilteredTablePanel<Route> {

    /** The table shown, so that the same one handed again is not compared row by row. */
    private RouteTable shown = RouteTable.EMPTY;

    RoutesPanel() {
        super("Routes", "routes", List.of(
                new RowsModel.Column<>("From", String.class, Route::from),
                new RowsModel.Column<>("To", String.class, Route::to),
                new RowsModel.Column<>("Hops", Integer.class, route -> route.exists() ? route.hops() : null, "Hops",
                        "Links along the route: 1 for a direct one; empty when there is no route"),
                new RowsModel.Column<>("Route", String.class, RouteText::path, "Route",
                        "The robots the route passes, in order, the best by the rule of docs/routes.md"),
                new RowsModel.Column<>("Weakest hop", String.class, route -> RouteText.weakest(route.weakest()), "Weakest hop",
                        "The route's weakest link: the slowest with links shaped, the weakest in dBm without"),
                new RowsModel.Column<>("Rate bound", RateCell.class, route -> new RateCell(route.rateBound()), "Rate bound",
                        "With links shaped, the rate one stream could have over the whole route; - when not shaped or no route")));
        // A route of three hops whole, and at the size the window opens one of five or six; a longer one may be cut (its
        // whole text is the cell's tooltip), so that the Weakest hop and the Rate bound show beside it rather than a
        // sideways scroll away.
        leastWidths(StatsPanel.NAME, StatsPanel.NAME, "99", "Explorer1234 > Relay1 > Relay2 > Scout",
                "Explorer1234 > Relay1, -100.0 dBm, 54 Mbit/s", "54 Mbit/s");
        narrow(0, 1, 2, 4, 5); // the room the window has beyond the least widths goes to the route
    }

    /** Event thread: the routes of this table, every ordered pair's found already (off the event thread: {@link MapData#allRoutes}). */
    void show(RouteTable routes, List<Route> all) {
        if (routes != shown && !routes.equals(shown)) { // the same table at most ticks: no comparison then
            shown = routes;
            show(all);
        }
    }
}
