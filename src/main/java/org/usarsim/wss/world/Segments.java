package org.usarsim.wss.world;

/**
 * Whether two 2-D segments meet. They do when they cross, when an end of one lies on the other,
 * and when they overlap along a common line; in every case when they come within
 * {@link #TOUCH} metres of each other, so that rounding in a computed position never decides
 * whether a robot standing on a wall is behind it.
 */
final class Segments {

    /** Segments closer than this, in metres, touch. */
    static final double TOUCH = 1e-6;

    private Segments() {
    }

    /** Whether segment a-b and segment c-d cross or touch. Either may be a single point. */
    static boolean meet(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
        if (cross(ax, ay, bx, by, cx, cy, dx, dy)) {
            return true;
        }
        // Segments that do not cross are as close as the closest end of one to the other.
        return pointToSegment(ax, ay, cx, cy, dx, dy) <= TOUCH
                || pointToSegment(bx, by, cx, cy, dx, dy) <= TOUCH
                || pointToSegment(cx, cy, ax, ay, bx, by) <= TOUCH
                || pointToSegment(dx, dy, ax, ay, bx, by) <= TOUCH;
    }

    /** Whether segment a-b and segment c-d cross properly: each one's ends strictly either side of the other. */
    static boolean cross(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
        return opposite(side(cx, cy, dx, dy, ax, ay), side(cx, cy, dx, dy, bx, by))
                && opposite(side(ax, ay, bx, by, cx, cy), side(ax, ay, bx, by, dx, dy));
    }

    /** Positive when p is left of the line from s to e, negative when right, 0 on it. */
    private static double side(double sx, double sy, double ex, double ey, double px, double py) {
        return (ex - sx) * (py - sy) - (ey - sy) * (px - sx);
    }

    private static boolean opposite(double u, double v) {
        return (u > 0 && v < 0) || (u < 0 && v > 0);
    }

    /** The distance from point p to the segment s-e (a point when s equals e). */
    static double pointToSegment(double px, double py, double sx, double sy, double ex, double ey) {
        double vx = ex - sx;
        double vy = ey - sy;
        double lengthSquared = vx * vx + vy * vy;
        double f = lengthSquared == 0 ? 0 : ((px - sx) * vx + (py - sy) * vy) / lengthSquared;
        f = Math.max(0, Math.min(1, f));
        return Math.hypot(px - (sx + f * vx), py - (sy + f * vy));
    }
}
