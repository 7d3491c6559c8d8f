package org.usarsim.wss.world;

/** How a robot of the world file moves: where it is at a time since the world started. */
sealed interface Motion permits Route, Track {

    /** Where the robot is {@code seconds} after the world started (0 or more). */
    Point at(double seconds);
}
