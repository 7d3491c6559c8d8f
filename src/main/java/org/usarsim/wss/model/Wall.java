package org.usarsim.wss.model;

/** A wall seen from above, as the simulator gives it: a segment from (x1, y1) to (x2, y2), in metres. */
public record Wall(double x1, double y1, double x2, double y2) {
}
