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
 * the robots cut off, every ordered pair's route that exists), each route's JSON by its pair
 * ({@code from\nto}: what {@link #changesFrom} compares) and each robot's hops to the base
 * for /metrics. Made once per table on the publisher's thread (every robot's search: never on the
 * hub's or a request's thread), then shared read-only.
 */
record RoutesJson(RouteTable table, Map<String, Object> json, Map<String, Integer> hopsToBase, Map<String, Map<String, Object>> rows) {

    static final RoutesJson EMPTY = of(RouteTable.EMPTY);

    static RoutesJson of(RouteTable table) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("base", table.base());
        json.put("rule", table.rule().name());
        json.put("shaped", table.rule().shaped());
        json.put("cutOff", table.cutOff());
        Map<String, Map<String, Object>> rows = new LinkedHashMap<>();
        for (Route route : table.all()) {
            if (route.exists()) {
                rows.put(route.from() + '\n' + route.to(), route(route));
            }
        }
        json.put("routes", new ArrayList<>(rows.values()));
        Map<String, Integer> hops = new LinkedHashMap<>();
        if (table.base() != null) {
            for (String robot : table.robots()) {
                if (!robot.equals(table.base())) {
                    hops.put(robot, table.toBase(robot).hops());
                }
            }
        }
        return new RoutesJson(table, json, hops, rows);
    }

    /**
     * What a {@code routeChanges} event tells a stream that was told {@code before} (docs/monitor.md):
     * the robots cut off now, the routes that are new or changed, and the pairs whose route is gone;
     * empty lists when nothing of the JSON changed. Null when the whole is to be told instead: the
     * base, the rule or whether routes are shaped changed, or the changes are more than half the routes.
     */
    Map<String, Object> changesFrom(RoutesJson before) {
        for (String key : List.of("base", "rule", "shaped")) {
            if (!java.util.Objects.equals(before.json.get(key), json.get(key))) {
                return null;
            }
        }
        List<Map<String, Object>> changed = new ArrayList<>();
        rows.forEach((pair, route) -> {
            if (!route.equals(before.rows.get(pair))) {
                changed.add(route);
            }
        });
        List<Map<String, Object>> gone = new ArrayList<>();
        before.rows.forEach((pair, route) -> {
            if (!rows.containsKey(pair)) {
                Map<String, Object> ends = new LinkedHashMap<>();
                ends.put("from", route.get("from"));
                ends.put("to", route.get("to"));
                gone.add(ends);
            }
        });
        if (2 * (changed.size() + gone.size()) > Math.max(rows.size(), before.rows.size())) {
            return null;
        }
        Map<String, Object> changes = new LinkedHashMap<>();
        changes.put("cutOff", json.get("cutOff"));
        changes.put("routes", changed);
        changes.put("gone", gone);
        return changes;
    }

    /**
     * A route as the state and the events tell it: its hops as the path says them (hop i from
     * {@code path[i]} to {@code path[i + 1]}), each leg only its strength and rate, the weakest as
     * the index of its leg; the table says whether it is shaped (100 robots' table in 2.3 MB, not 4.7).
     */
    private static Map<String, Object> route(Route route) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("from", route.from());
        json.put("to", route.to());
        json.put("hops", route.hops());
        json.put("path", route.path());
        json.put("legs", route.legs().stream().map(RoutesJson::leg).toList());
        json.put("weakest", route.legs().indexOf(route.weakest()));
        json.put("rateBound", route.rateBound());
        return json;
    }

    /** A leg: {@code [strength, rate]}, the strength in dBm or null, the rate in bit/s (0 unshaped). */
    private static List<Object> leg(Hop hop) {
        List<Object> json = new ArrayList<>(2);
        json.add(StateJson.number(hop.strength()));
        json.add(hop.bitsPerSecond());
        return json;
    }

    /** The robots cut off from the base (none without a base). */
    int cutOff() {
        return ((List<?>) json.get("cutOff")).size();
    }
}
