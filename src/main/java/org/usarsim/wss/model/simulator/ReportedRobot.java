package org.usarsim.wss.model.simulator;

/** Where the simulator says a robot is, in metres, and whether its battery is empty. */
public record ReportedRobot(String name, double x, double y, double z, boolean batteryEmpty) {

    /** The 3-D distance in metres. */
    public double distanceTo(ReportedRobot other) {
        double dx = x - other.x;
        double dy = y - other.y;
        double dz = z - other.z;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
