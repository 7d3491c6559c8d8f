package org.usarsim.wss.attach;

import java.util.List;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.routes.RouteTable;

/**
 * What an attached window shows of the server at one instant, built from its monitor's snapshot and
 * the events after it (docs/monitor.md): the hub's four tables, the map (robots with position and
 * range, a line per pair, the walls, the cutoff), the model's name, the control port, and whether
 * the token is an operator's, and the server's routes (its table and every ordered pair's route,
 * those without one too: the Routes tab's rows). Never changed after.
 */
public record ServerView(HubSnapshot hub, List<MapRobot> robots, List<MapLine> lines, List<Wall> walls, double cutoff,
        String model, int controlPort, boolean operator, RouteTable routes, List<Route> allRoutes) {

    public ServerView {
        robots = List.copyOf(robots);
        lines = List.copyOf(lines);
        walls = List.copyOf(walls);
        allRoutes = List.copyOf(allRoutes);
    }

    /** A robot on the map: its position (null when the model has none) and range through open space (NaN: none). */
    public record MapRobot(String name, Position position, double range) {
    }

    /** A pair on the map: its state, the model's strength now (NaN unknown), the link rate (bit/s, 0: not shaped). */
    public record MapLine(String first, String second, PairState state, double strength, long rate) {
    }
}
