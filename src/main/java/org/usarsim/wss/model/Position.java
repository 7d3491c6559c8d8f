package org.usarsim.wss.model;

/** Where a robot is in the simulator, in metres (USARSim's frame: x and y on the floor, z up). */
public record Position(double x, double y, double z) {

    /** The straight-line distance to another position, in metres. */
    public double distanceTo(Position other) {
        double dx = x - other.x;
        double dy = y - other.y;
        double dz = z - other.z;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
