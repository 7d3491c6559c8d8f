package org.usarsim.wss.model.simulator;

import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.ros.OccupancyGrid;

/**
 * The walls a rosbridge source counts obstacles on (docs/ros.md, "Walls and grids"): the last
 * {@code nav_msgs/OccupancyGrid} from the map topic, and its walls for the map (the same list while
 * they are the same). Taken on the WebSocket's thread, read by the poller: under this object's lock.
 */
final class GridCounts {

    private OccupancyGrid grid;
    private List<Wall> walls;

    /** Takes a grid; true when it is the first this object took. */
    boolean took(OccupancyGrid taken) {
        List<Wall> given = GridWalls.of(taken);
        synchronized (this) {
            boolean first = grid == null;
            grid = taken;
            if (!given.equals(walls)) {
                walls = given;
            }
            return first;
        }
    }

    /** The grid's walls; null before a grid came. */
    synchronized List<Wall> walls() {
        return walls;
    }

    /** The walls of the grid between each pair whose robots are both {@code listed}; none before a grid came. */
    Map<RobotPair, Double> between(Collection<RobotPair> pairs, Map<String, ReportedRobot> listed) {
        OccupancyGrid counted;
        synchronized (this) {
            counted = grid;
        }
        Map<RobotPair, Double> counts = new HashMap<>();
        if (counted == null) {
            return counts;
        }
        for (RobotPair pair : pairs) {
            ReportedRobot a = listed.get(pair.first());
            ReportedRobot b = listed.get(pair.second());
            if (a != null && b != null) {
                counts.put(pair, (double) counted.crossings(a.x(), a.y(), b.x(), b.y()));
            }
        }
        return counts;
    }
}
