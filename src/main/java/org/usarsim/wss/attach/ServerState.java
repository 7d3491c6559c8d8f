package org.usarsim.wss.attach;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonNode;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.routes.RouteTable;

/**
 * The server as the monitor's snapshot and events tell it (docs/monitor.md): each entry by its key,
 * an event with a known key replacing it whole, {@code removed} taking it away, {@code snapshot}
 * replacing everything; {@code routes} replacing the route table, {@code routeChanges} the routes
 * it names, every ordered pair's route listed once per change. One thread (the client's) changes and reads it; {@link #view} copies it out.
 */
final class ServerState {

    private final Map<String, HubSnapshot.RobotEntry> robots = new LinkedHashMap<>();
    private final Map<String, ServerView.MapRobot> mapRobots = new LinkedHashMap<>();
    private final Map<String, HubSnapshot.PortEntry> ports = new LinkedHashMap<>();
    private final Map<String, HubSnapshot.LinkEntry> links = new LinkedHashMap<>();
    private final Map<String, HubSnapshot.PairEntry> pairs = new LinkedHashMap<>();
    private final Map<String, ServerView.MapLine> lines = new LinkedHashMap<>();
    private List<Wall> walls = List.of();
    private double cutoff = Double.NaN;
    private String model = "";
    private int controlPort;
    private boolean operator;
    /** The replay object of the last snapshot or event, null while none runs. */
    private JsonNode replay;
    /**
     * The last routes object told (null: none), its routes by pair ({@code from\nto}, as
     * {@code routeChanges} events left them), the table made of them and every ordered pair's route
     * (made once per change).
     */
    private JsonNode routesJson;
    private final Map<String, JsonNode> routeRows = new LinkedHashMap<>();
    private RouteTable routes = RouteTable.EMPTY;
    private List<Route> allRoutes = List.of();

    /** The whole state of GET /api/state or a {@code snapshot} event. */
    void replace(JsonNode state) throws JsonException {
        robots.clear();
        mapRobots.clear();
        ports.clear();
        links.clear();
        pairs.clear();
        lines.clear();
        operator = state.get("operator").bool();
        JsonNode server = state.optional("server");
        JsonNode port = server == null ? null : server.optional("controlPort");
        controlPort = port == null || port.isNull() ? 0 : (int) port.integer(0, 65535);
        model(state.get("model"));
        JsonNode replayed = state.optional("replay");
        replay = replayed == null || replayed.isNull() ? null : replayed;
        for (String kind : List.of("robot", "port", "link", "pair", "line")) {
            for (JsonNode entry : state.get(kind + "s").items()) {
                put(kind, entry);
            }
        }
        routes(state.optional("routes"));
    }

    /** A routes object: the table and its rows, over the robots known now. */
    private void routes(JsonNode json) throws JsonException {
        routesJson = json;
        routeRows.clear();
        if (json != null && !json.isNull()) {
            for (JsonNode route : json.get("routes").items()) {
                routeRows.put(routeKey(route), route);
            }
        }
        tableAgain();
    }

    /** A {@code routeChanges} event: the routes new or changed replace theirs, those gone go. */
    private void routeChanges(JsonNode changes) throws JsonException {
        if (routesJson == null || routesJson.isNull()) {
            throw changes.problem("route changes before any routes");
        }
        for (JsonNode route : changes.get("routes").items()) {
            routeRows.put(routeKey(route), route);
        }
        for (JsonNode gone : changes.get("gone").items()) {
            routeRows.remove(routeKey(gone));
        }
        tableAgain();
    }

    private static String routeKey(JsonNode route) throws JsonException {
        return route.get("from").string() + '\n' + route.get("to").string();
    }

    /** The table and its rows made again from the routes told, over the robots known now. */
    private void tableAgain() throws JsonException {
        routes = StateReader.routes(routesJson, routeRows.values(), robots.keySet());
        allRoutes = routes.all();
    }

    /** One event other than {@code snapshot} and {@code log}; false when its type is not the state's. */
    boolean apply(String type, JsonNode data) throws JsonException {
        switch (type) {
            case "robots", "ports", "links", "pairs", "lines" -> {
                String kind = type.substring(0, type.length() - 1);
                for (JsonNode entry : data.items()) {
                    put(kind, entry);
                }
            }
            case "model" -> model(data);
            case "replay" -> replay = data.isNull() ? null : data;
            case "routes" -> routes(data);
            case "routeChanges" -> routeChanges(data);
            case "removed" -> removed(data);
            default -> {
                return false;
            }
        }
        return true;
    }

    /** {@code removed}: an object of lists, each present only when not empty; robots by name. */
    private void removed(JsonNode data) throws JsonException {
        boolean routesGone = false;
        for (String kind : List.of("robot", "port", "link", "pair", "line")) {
            JsonNode gone = data.optional(kind + "s");
            if (gone == null) {
                continue;
            }
            for (JsonNode entry : gone.items()) {
                String key = kind.equals("robot") ? entry.string() : StateReader.key(kind, entry);
                switch (kind) {
                    case "robot" -> {
                        robots.remove(key);
                        mapRobots.remove(key);
                        routesGone = true;
                    }
                    case "port" -> ports.remove(key);
                    case "link" -> links.remove(key);
                    case "pair" -> pairs.remove(key);
                    default -> lines.remove(key);
                }
            }
        }
        if (routesGone) {
            tableAgain(); // the Routes tab's rows are the robots known now
        }
    }

    /** The replay's object (time, duration, speed, playing, poll) while one runs, else null. */
    JsonNode replay() {
        return replay;
    }

    private void model(JsonNode node) throws JsonException {
        JsonNode name = node.optional("name");
        model = name == null || name.isNull() ? "" : name.string();
        cutoff = StateReader.number(node.optional("cutoff"));
        walls = StateReader.walls(node);
    }

    private void put(String kind, JsonNode entry) throws JsonException {
        String key = StateReader.key(kind, entry);
        switch (kind) {
            case "robot" -> {
                robots.put(key, StateReader.robot(entry));
                mapRobots.put(key, StateReader.mapRobot(entry));
            }
            case "port" -> ports.put(key, StateReader.port(entry));
            case "link" -> links.put(key, StateReader.link(entry));
            case "pair" -> pairs.put(key, StateReader.pair(entry));
            default -> lines.put(key, StateReader.line(entry));
        }
    }

    /** A copy of what is known now, each list in the hub's order. */
    ServerView view() {
        HubSnapshot hub = new HubSnapshot(
                sorted(robots, Comparator.comparing(HubSnapshot.RobotEntry::name)),
                sorted(ports, Comparator.comparing(HubSnapshot.PortEntry::from).thenComparing(HubSnapshot.PortEntry::to)
                        .thenComparingInt(HubSnapshot.PortEntry::targetPort)),
                sorted(links, Comparator.comparing(HubSnapshot.LinkEntry::from).thenComparing(HubSnapshot.LinkEntry::to)
                        .thenComparingInt(HubSnapshot.LinkEntry::targetPort)),
                sorted(pairs, Comparator.comparing(HubSnapshot.PairEntry::first).thenComparing(HubSnapshot.PairEntry::second)));
        return new ServerView(hub, sorted(mapRobots, Comparator.comparing(ServerView.MapRobot::name)),
                sorted(lines, Comparator.comparing(ServerView.MapLine::first).thenComparing(ServerView.MapLine::second)),
                walls, cutoff, model, controlPort, operator, routes, allRoutes);
    }

    private static <T> List<T> sorted(Map<String, T> entries, Comparator<T> order) {
        List<T> list = new ArrayList<>(entries.values());
        list.sort(order);
        return list;
    }
}
