package org.usarsim.wss.world;

/** A robot at one moment: where it is and whether its battery is empty. */
record RobotAt(String name, Point position, boolean batteryEmpty) {
}
