package org.usarsim.wss.gui;

import java.util.ArrayList;
import java.util.List;
import org.usarsim.wss.routes.Hop;
import org.usarsim.wss.routes.Route;

/**
 * The route the map draws for a complete {@link RoutePick}: the route of the map's route table
 * (one that may not exist), and each of its hops in order with the strength and rate its pair's
 * line has on the map, and whether links are shaped (a hop is labelled with its rate then, with
 * its strength otherwise). Immutable; what {@link MapPanel#route} says the map draws.
 */
record DrawnRoute(Route route, List<Hop> hops, boolean shaped) {

    DrawnRoute {
        hops = List.copyOf(hops);
    }

    /** The route the map draws for this pick over this picture; null while the pick is not complete. */
    static DrawnRoute of(RoutePick pick, MapData data) {
        if (!pick.complete()) {
            return null;
        }
        Route route = data.routes().route(pick.from(), pick.to());
        List<Hop> hops = new ArrayList<>();
        for (int i = 1; i < route.path().size(); i++) {
            String a = route.path().get(i - 1);
            String b = route.path().get(i);
            MapData.Line line = data.line(a, b);
            hops.add(line == null ? new Hop(a, b, Double.NaN, 0) : new Hop(a, b, line.strength(), line.rate()));
        }
        return new DrawnRoute(route, hops, data.routes().rule().shaped());
    }

    /** The map's status line for it ({@link RouteText#status}). */
    String status(RoutePick pick) {
        return RouteText.status(pick, route, shaped);
    }
}
