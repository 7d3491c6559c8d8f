package org.usarsim.wss.world;

/** A place in the world, in metres: x and y on the floor, z up. */
record Point(double x, double y, double z) {

    /** The point a fraction {@code f} (0 to 1) of the way from here to {@code to}; exactly here at 0. */
    Point towards(Point to, double f) {
        return new Point(x + (to.x - x) * f, y + (to.y - y) * f, z + (to.z - z) * f);
    }

    double distanceTo(Point other) {
        double dx = other.x - x;
        double dy = other.y - y;
        double dz = other.z - z;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
