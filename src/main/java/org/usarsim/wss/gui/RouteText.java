package org.usarsim.wss.gui;

import java.util.List;
import java.util.Locale;
import org.usarsim.wss.routes.Hop;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.shaping.Bitrate;

/**
 * How the window says a route (docs/gui.md, "Routes"): the map's status line, a hop's label on
 * the map, and the Routes table's Route and Weakest hop cells. One place, pure.
 */
final class RouteText {

    /** What the map's status line says while nothing is picked. */
    static final String HOW = "Click a robot, then another: the best route between them is drawn (a third click or Escape clears)";

    private RouteText() {
    }

    /**
     * The map's status line for this pick, {@code route} the route of a complete pick (else
     * ignored): how to pick, the start picked, or the route ("Alpha -> Scout: 3 hops via R1, R2,
     * bound 1.2 Mbit/s"; unshaped, its weakest hop's strength), or that there is none.
     */
    static String status(RoutePick pick, Route route, boolean shaped) {
        if (pick.from() == null) {
            return HOW;
        }
        if (!pick.complete()) {
            return "Route from " + pick.from() + ": click another robot (a click on " + pick.from() + " or Escape clears)";
        }
        String ends = pick.from() + " -> " + pick.to() + ": ";
        if (route == null || !route.exists()) {
            return ends + "no route (no chain of links up joins them)";
        }
        List<String> relays = route.path().subList(1, route.path().size() - 1);
        String hops = route.hops() == 1 ? "1 hop, direct" : route.hops() + " hops via " + String.join(", ", relays);
        if (shaped) {
            return ends + hops + ", bound " + Bitrate.format(route.rateBound()) + weakestAt(route.weakest(), shaped);
        }
        return ends + hops + weakestAt(route.weakest(), shaped);
    }

    private static String weakestAt(Hop weakest, boolean shaped) {
        if (weakest == null) {
            return "";
        }
        String value = shaped ? Bitrate.format(weakest.bitsPerSecond()) : strength(weakest.strength());
        return value.isEmpty() ? "" : "; weakest hop " + weakest.from() + " -> " + weakest.to() + " at " + value;
    }

    /** A hop's label on the map: its rate with links shaped ("54 Mbit/s"), its strength without ("-71.3 dBm"); empty when unknown. */
    static String hopLabel(Hop hop, boolean shaped) {
        if (shaped) {
            return hop.bitsPerSecond() > 0 ? Bitrate.format(hop.bitsPerSecond()) : "";
        }
        return strength(hop.strength());
    }

    /** The Routes table's Route cell: the robots in order, "Alpha > R1 > Scout"; "no route" when there is none. */
    static String path(Route route) {
        return route.exists() ? String.join(" > ", route.path()) : "no route";
    }

    /** The Routes table's Weakest hop cell: "R1 > Scout, -82.0 dBm, 6 Mbit/s" (the rate with links shaped); empty without a route. */
    static String weakest(Hop hop) {
        if (hop == null) {
            return "";
        }
        StringBuilder text = new StringBuilder(hop.from() + " > " + hop.to());
        String strength = strength(hop.strength());
        if (!strength.isEmpty()) {
            text.append(", ").append(strength);
        }
        if (hop.bitsPerSecond() > 0) {
            text.append(", ").append(Bitrate.format(hop.bitsPerSecond()));
        }
        return text.toString();
    }

    /** A strength as the map says it, "-71.3 dBm"; empty when unknown. */
    static String strength(double dBm) {
        return Double.isNaN(dBm) || Double.isInfinite(dBm) ? "" : String.format(Locale.ROOT, "%.1f dBm", dBm);
    }
}
