package org.usarsim.wss.world;

import java.util.List;
import java.util.Optional;

/** The world at one moment: every robot's state, in file order, and the walls. Immutable. */
record Snapshot(List<RobotAt> robots, List<Wall> walls) {

    Snapshot {
        robots = List.copyOf(robots);
        walls = List.copyOf(walls);
    }

    Optional<RobotAt> robot(String name) {
        return robots.stream().filter(robot -> robot.name().equals(name)).findFirst();
    }

    /**
     * How many walls the straight line on the floor between two robots crosses or touches; -1
     * when either robot is not in the world.
     */
    int obstacles(String from, String to) {
        Optional<RobotAt> a = robot(from);
        Optional<RobotAt> b = robot(to);
        if (a.isEmpty() || b.isEmpty()) {
            return -1;
        }
        Point p = a.get().position();
        Point q = b.get().position();
        return (int) walls.stream().filter(wall -> wall.blocks(p, q)).count();
    }
}
