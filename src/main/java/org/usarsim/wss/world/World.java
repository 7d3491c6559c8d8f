package org.usarsim.wss.world;

import java.util.List;

/** The robots (in file order) and the walls of a world file; immutable. */
final class World {

    private final List<WorldRobot> robots;
    private final List<Wall> walls;

    World(List<WorldRobot> robots, List<Wall> walls) {
        this.robots = List.copyOf(robots);
        this.walls = List.copyOf(walls);
    }

    /** The world {@code seconds} after it started: a pure function of the time. */
    Snapshot at(double seconds) {
        checked(seconds);
        return new Snapshot(robots.stream().map(robot -> robot.at(seconds)).toList(), walls);
    }

    /** One robot (its index in file order) {@code seconds} after the world started. */
    RobotAt robotAt(int index, double seconds) {
        return robots.get(index).at(checked(seconds));
    }

    private static double checked(double seconds) {
        if (!(seconds >= 0) || Double.isInfinite(seconds)) {
            throw new IllegalArgumentException("a time from 0 on, in seconds: " + seconds);
        }
        return seconds;
    }

    /** The robots' names, in file order. */
    List<String> robotNames() {
        return robots.stream().map(WorldRobot::name).toList();
    }

    int robotCount() {
        return robots.size();
    }

    List<Wall> walls() {
        return walls;
    }

    int wallCount() {
        return walls.size();
    }
}
