package org.usarsim.wss.monitor;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.routes.Hop;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.routes.RouteTable;

/**
 * One route table as the monitor tells it (docs/monitor.md, "routes"): its JSON (the base, the rule,
 * the robots cut off, every ordered pair's route that exists) and each robot's hops to the base
 * for /metrics. Made once per table on the publisher's thread (every robot's search: never on the
 * hub's or a request's thread), then shared read-only.
 */
record RoutesJson(RouteTable table, Map<String, Object> json, Map<String, Integer> hopsToBase) {

    static final RoutesJson EMPTY = of(RouteTable.EMPTY);

    static RoutesJson of(RouteTable table) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("base", table.base());
        json.put("rule", table.rule().name());
        json.put("shaped", table.rule().shaped());
        json.put("cutOff", table.cutOff());
        List<Map<String, Object>> routes = new ArrayList<>();
        for (Route route : table.all()) {
            if (route.exists()) {
                routes.add(route(route, table.rule().shaped()));
            }
        }
        json.put("routes", routes);
        Map<String, Integer> hops = new LinkedHashMap<>();
        if (table.base() != null) {
            for (String robot : table.robots()) {
                if (!robot.equals(table.base())) {
                    hops.put(robot, table.toBase(robot).hops());
                }
            }
        }
        return new RoutesJson(table, json, hops);
    }

    private static Map<String, Object> route(Route route, boolean shaped) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("from", route.from());
        json.put("to", route.to());
        json.put("hops", route.hops());
        json.put("path", route.path());
        json.put("legs", route.legs().stream().map(RoutesJson::hop).toList());
        json.put("weakest", hop(route.weakest()));
        json.put("rateBound", route.rateBound());
        json.put("shaped", shaped);
        return json;
    }

    private static Map<String, Object> hop(Hop hop) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("from", hop.from());
        json.put("to", hop.to());
        json.put("strength", StateJson.number(hop.strength()));
        json.put("rate", hop.bitsPerSecond());
        return json;
    }

    /** The robots cut off from the base (none without a base). */
    int cutOff() {
        return ((List<?>) json.get("cutOff")).size();
    }
}
