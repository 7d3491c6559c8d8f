package org.usarsim.wss.gui;

import java.util.List;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.routes.RouteTable;

/**
 * "Routes": a row per ordered pair of registered robots, its best route now (docs/routes.md): From,
 * To, Hops (empty when there is none), Route (the robots in order, or "no route"), Weakest hop
 * (its pair, strength and with links shaped rate) and Rate bound (with links shaped, the rate
 * one stream could have over the whole route; {@link RateCell}). Filtered as the other tables, by
 * "From To"; rows replaced only when the route table changed.
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
        leastWidths(StatsPanel.NAME, StatsPanel.NAME, "99", "Explorer1234 > Relay > Explorer1234", "Explorer1234 > Relay, -100.0 dBm, 54 Mbit/s",
                "54 Mbit/s");
        // A long route: the column grows to it (and the table scrolls sideways) rather than cut it.
        fitsContent(ROUTE_COLUMN);
    }

    /** The Route column, by model index. */
    private static final int ROUTE_COLUMN = 3;

    /** Event thread: the routes of this table. */
    void show(RouteTable routes) {
        if (!routes.equals(shown)) {
            shown = routes;
            show(routes.all());
        }
    }
}
