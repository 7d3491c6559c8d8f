package org.usarsim.wss.gui;

import java.util.List;
import org.usarsim.wss.routes.Hop;
import org.usarsim.wss.routes.Route;

/**
 * The route the map draws for a complete {@link RoutePick}: the route of the map's route table
 * (one that may not exist: no hops), and whether links are shaped (a hop is labelled with its rate
 * then, with its strength otherwise). Immutable; what {@link MapPanel#route} says the map draws.
 */
record DrawnRoute(Route route, boolean shaped) {

    /** The route the map draws for this pick over this picture; null while the pick is not complete. */
    static DrawnRoute of(RoutePick pick, MapData data) {
        return pick.complete() ? new DrawnRoute(data.routes().route(pick.from(), pick.to()), data.routes().rule().shaped()) : null;
    }

    /** Its hops in order, each with its strength and rate that way. */
    List<Hop> hops() {
        return route.legs();
    }
}
