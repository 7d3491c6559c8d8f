package org.usarsim.wss.gui;

import java.util.ArrayList;
import java.util.List;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.MapLines;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.routes.RouteTable;

/**
 * What the map shows at one instant, gathered off the event thread (NetworkView) and never changed
 * after: the robots (each with its position, or null when the model has none, and its range
 * through open space, NaN when the model has none), a line per pair (with its rate when links are
 * shaped), the walls, the model's cutoff (NaN when it has none) and the server's routes (its
 * base, the robots cut off from it, each pair's best route: docs/routes.md), with every ordered
 * pair's route found already ({@code allRoutes}: the Routes tab's rows; finding them is the search
 * the event thread must not do).
 */
record MapData(List<Robot> robots, List<Line> lines, List<Wall> walls, double cutoff, RouteTable routes, List<Route> allRoutes) {

    static final MapData EMPTY = new MapData(List.of(), List.of(), List.of(), Double.NaN);

    MapData {
        robots = List.copyOf(robots);
        lines = List.copyOf(lines);
        walls = List.copyOf(walls);
        java.util.Objects.requireNonNull(routes);
        allRoutes = List.copyOf(allRoutes);
    }

    /** Without routes. */
    MapData(List<Robot> robots, List<Line> lines, List<Wall> walls, double cutoff) {
        this(robots, lines, walls, cutoff, RouteTable.EMPTY, List.of());
    }

    /**
     * Gathers the map of the hub's robots from the model (its query methods only: quick, and never
     * the hub's lock): positions, open-space ranges, walls and cutoff, and a line for every pair of
     * registered robots, in the state the snapshot's pairs give it (forced ones included) with its
     * link rate, or, for a pair the hub has not seen yet, up or broken as the model allows (no
     * rate). Strengths are the model's now. Off the event thread.
     */
    static MapData gather(HubSnapshot hub, PropagationModel model) {
        return gather(hub, model, RouteTable.EMPTY, List.of());
    }

    /**
     * As {@link #gather(HubSnapshot, PropagationModel)}, with the server's routes (its base, who is
     * cut off, each pair's route) and every ordered pair's route found ({@link RouteTable#all}).
     */
    static MapData gather(HubSnapshot hub, PropagationModel model, RouteTable routes, List<Route> allRoutes) {
        List<Robot> robots = new ArrayList<>();
        for (HubSnapshot.RobotEntry entry : hub.robots()) {
            String name = entry.name();
            robots.add(new Robot(name, model.positionOf(name).orElse(null), model.rangeFor(name, name)));
        }
        List<Line> lines = new ArrayList<>();
        for (MapLines.Line line : MapLines.of(robots.stream().map(Robot::name).toList(), hub, model)) {
            lines.add(new Line(line.first(), line.second(), line.state(), line.strength(), line.rate()));
        }
        return new MapData(robots, lines, model.walls(), model.cutoff(), routes, allRoutes);
    }

    /** A pair's link rate for the map ({@link MapLines#rateOf}). */
    static long rateOf(HubSnapshot.PairEntry pair) {
        return MapLines.rateOf(pair);
    }

    /** A registered robot; {@code position} null when the model does not know it. */
    record Robot(String name, Position position, double range) {
    }

    /**
     * A pair of robots, names in ascending order: its state, the model's strength (dBm, NaN
     * unknown) and with links shaped its link rate ({@link #rateOf}; 0: not shaped, or a pair the
     * hub has not seen yet).
     */
    record Line(String first, String second, PairState state, double strength, long rate) {

        boolean forced() {
            return state.isForced();
        }
    }

    /** The line of the pair (names in either order), or null. */
    Line line(String a, String b) {
        for (Line line : lines) {
            if (line.first().equals(a) && line.second().equals(b) || line.first().equals(b) && line.second().equals(a)) {
                return line;
            }
        }
        return null;
    }

    /** The robot of that name, or null. */
    Robot robot(String name) {
        return robots.stream().filter(robot -> robot.name().equals(name)).findFirst().orElse(null);
    }
}
