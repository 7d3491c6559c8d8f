package org.usarsim.wss.world;

import java.util.OptionalDouble;

/**
 * A robot of the world file: its name, where it starts, how it moves (a {@link Route}, a
 * {@link Track}; none: it stands still) and how many seconds its battery lasts (none: forever).
 */
record WorldRobot(String name, Point start, Motion motion, OptionalDouble batterySeconds) {

    RobotAt at(double seconds) {
        Point position = motion == null ? start : motion.at(seconds);
        boolean empty = batterySeconds.isPresent() && seconds >= batterySeconds.getAsDouble();
        return new RobotAt(name, position, empty);
    }
}
