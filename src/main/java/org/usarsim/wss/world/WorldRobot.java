package org.usarsim.wss.world;

import java.util.OptionalDouble;

/**
 * A robot of the world file: its name, where it starts, the route it drives (none: it stands
 * still) and how many seconds its battery lasts (none: forever).
 */
record WorldRobot(String name, Point start, Route route, OptionalDouble batterySeconds) {

    RobotAt at(double seconds) {
        Point position = route == null ? start : route.at(seconds);
        boolean empty = batterySeconds.isPresent() && seconds >= batterySeconds.getAsDouble();
        return new RobotAt(name, position, empty);
    }
}
