package org.usarsim.wss.attach;

import java.util.ArrayList;
import java.util.List;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.hub.core.UdpCounts;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonNode;
import org.usarsim.wss.routes.Hop;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.routes.RouteRule;
import org.usarsim.wss.routes.RouteTable;

/**
 * The monitor's JSON objects (docs/monitor.md, "GET /api/state") read into the hub's and the map's
 * records, and the key that names each entry in the events. Unknown fields are ignored; a
 * {@code null} number is NaN.
 */
final class StateReader {

    private StateReader() {
    }

    static HubSnapshot.RobotEntry robot(JsonNode robot) throws JsonException {
        List<Integer> ports = new ArrayList<>();
        for (JsonNode port : robot.get("ports").items()) {
            ports.add((int) port.integer(0, 65535));
        }
        return new HubSnapshot.RobotEntry(robot.get("name").string(), robot.get("address").string(), ports,
                number(robot.optional("airtime")));
    }

    static ServerView.MapRobot mapRobot(JsonNode robot) throws JsonException {
        JsonNode at = robot.optional("position");
        Position position = at == null || at.isNull() ? null
                : new Position(at.get("x").number(), at.get("y").number(), number(at.optional("z")));
        return new ServerView.MapRobot(robot.get("name").string(), position, number(robot.optional("range")));
    }

    static HubSnapshot.PortEntry port(JsonNode port) throws JsonException {
        return new HubSnapshot.PortEntry(port.get("from").string(), port.get("to").string(), (int) port.get("targetPort").integer(0, 65535),
                (int) port.get("wssPort").integer(0, 65535), port.get("listening").bool(),
                HubSnapshot.PortKind.valueOf(port.get("kind").string()));
    }

    static HubSnapshot.LinkEntry link(JsonNode link) throws JsonException {
        return new HubSnapshot.LinkEntry(link.get("from").string(), link.get("to").string(), (int) link.get("targetPort").integer(0, 65535),
                (int) link.get("wssPort").integer(0, 65535), (int) link.get("outgoingPort").integer(0, 65535));
    }

    static HubSnapshot.PairEntry pair(JsonNode pair) throws JsonException {
        JsonNode lastClose = pair.optional("lastClose");
        return new HubSnapshot.PairEntry(pair.get("first").string(), pair.get("second").string(), state(pair.get("state")),
                number(pair.optional("strength")), number(pair.optional("distance")),
                count(pair, "bytesFirstToSecond"), count(pair, "bytesSecondToFirst"),
                number(pair.optional("rateFirstToSecond")), number(pair.optional("rateSecondToFirst")),
                count(pair, "connections"), count(pair, "breaks"), count(pair, "resumes"), number(pair.optional("upShare")),
                lastClose == null || lastClose.isNull() ? null : lastClose.string(),
                count(pair, "linkRateFirstToSecond"), count(pair, "linkRateSecondToFirst"),
                udp(pair.optional("udpFirstToSecond")), udp(pair.optional("udpSecondToFirst")));
    }

    static ServerView.MapLine line(JsonNode line) throws JsonException {
        return new ServerView.MapLine(line.get("first").string(), line.get("second").string(), state(line.get("state")),
                number(line.optional("strength")), count(line, "rate"));
    }

    static List<Wall> walls(JsonNode model) throws JsonException {
        JsonNode walls = model.optional("walls");
        List<Wall> read = new ArrayList<>();
        if (walls != null && !walls.isNull()) {
            for (JsonNode wall : walls.items()) {
                read.add(new Wall(wall.get("x1").number(), wall.get("y1").number(), wall.get("x2").number(), wall.get("y2").number()));
            }
        }
        return read;
    }

    /**
     * The {@code routes} object's base and rule (absent or null: no routes) with {@code rows} for
     * its routes (its own list, as {@code routeChanges} events left it), as a table of the routes
     * found on the server, over the robots named in {@code robots} (the state's, by name) and in the routes.
     */
    static RouteTable routes(JsonNode routes, Iterable<JsonNode> rows, java.util.Collection<String> robots) throws JsonException {
        if (routes == null || routes.isNull()) {
            return RouteTable.EMPTY;
        }
        RouteRule rule;
        try {
            rule = RouteRule.valueOf(routes.get("rule").string());
        } catch (IllegalArgumentException e) {
            throw routes.get("rule").problem("not a route rule: " + routes.get("rule").string());
        }
        JsonNode base = routes.optional("base");
        List<Route> read = new ArrayList<>();
        for (JsonNode route : rows) {
            List<String> path = new ArrayList<>();
            for (JsonNode robot : route.get("path").items()) {
                path.add(robot.string());
            }
            List<JsonNode> told = route.get("legs").items();
            if (told.size() != path.size() - 1) {
                throw route.get("legs").problem("a leg for each hop of the path, not " + told.size() + " for " + (path.size() - 1));
            }
            List<Hop> legs = new ArrayList<>();
            for (int i = 0; i < told.size(); i++) {
                List<JsonNode> leg = told.get(i).items();
                if (leg.size() != 2) {
                    throw told.get(i).problem("a leg is [strength, rate]");
                }
                legs.add(new Hop(path.get(i), path.get(i + 1), number(leg.get(0)), leg.get(1).integer(0, Long.MAX_VALUE)));
            }
            int weakest = (int) route.get("weakest").integer(0, legs.size() - 1);
            read.add(new Route(route.get("from").string(), route.get("to").string(), path, legs, legs.get(weakest),
                    count(route, "rateBound")));
        }
        List<String> named = new ArrayList<>(robots); // and those the routes name: the two may come in either order
        read.forEach(route -> named.addAll(route.path()));
        return RouteTable.known(rule, base == null || base.isNull() ? null : base.string(), named, read);
    }

    /** The key of a robot, port, link, pair or line in the events: its identifying fields, joined. */
    static String key(String kind, JsonNode entry) throws JsonException {
        return switch (kind) {
            case "robot" -> entry.get("name").string();
            case "port" -> entry.get("from").string() + '\n' + entry.get("to").string() + '\n' + whole(entry, "targetPort") + '\n'
                    + whole(entry, "wssPort");
            case "link" -> key("port", entry) + '\n' + whole(entry, "outgoingPort");
            case "pair", "line" -> entry.get("first").string() + '\n' + entry.get("second").string();
            default -> throw entry.problem("an entry of unknown kind " + kind);
        };
    }

    private static long whole(JsonNode entry, String field) throws JsonException {
        return entry.get(field).integer(0, 65535);
    }

    private static PairState state(JsonNode state) throws JsonException {
        try {
            return PairState.valueOf(state.string());
        } catch (IllegalArgumentException e) {
            throw state.problem("not a pair state: " + state.string());
        }
    }

    private static UdpCounts.Reading udp(JsonNode udp) throws JsonException {
        if (udp == null || udp.isNull()) {
            return UdpCounts.Reading.NONE;
        }
        return new UdpCounts.Reading(count(udp, "datagrams"), count(udp, "bytes"), count(udp, "droppedBroken"),
                count(udp, "droppedQueue"), count(udp, "lost"));
    }

    private static long count(JsonNode object, String field) throws JsonException {
        JsonNode value = object.optional(field);
        return value == null || value.isNull() ? 0 : value.integer(Long.MIN_VALUE, Long.MAX_VALUE);
    }

    /** A number, NaN for null or missing. */
    static double number(JsonNode value) throws JsonException {
        return value == null || value.isNull() ? Double.NaN : value.number();
    }
}
