package org.usarsim.wss.world;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * A robot's way through the world: from its start through each waypoint in straight lines at a
 * constant speed. A looping route then goes straight back to the start and repeats; any other
 * route stops at its last waypoint. Where the robot is depends on elapsed time alone.
 */
final class Route implements Motion {

    /** The corners in the order driven: the start, the waypoints, and the start again when looping. */
    private final Point[] corners;
    /** How far along the route each corner is, in metres; the last is the length of the route (of one lap). */
    private final double[] distances;
    private final double speed;
    private final boolean loop;

    Route(Point start, List<Point> waypoints, double speed, boolean loop) {
        if (!(speed > 0) || Double.isInfinite(speed)) {
            throw new IllegalArgumentException("speed " + speed);
        }
        List<Point> all = new ArrayList<>();
        all.add(start);
        all.addAll(waypoints);
        if (loop) {
            all.add(start);
        }
        this.corners = all.toArray(new Point[0]);
        this.distances = new double[corners.length];
        for (int i = 1; i < corners.length; i++) {
            distances[i] = distances[i - 1] + corners[i - 1].distanceTo(corners[i]);
        }
        this.speed = speed;
        this.loop = loop;
    }

    @Override
    public Point at(double seconds) {
        double length = distances[distances.length - 1];
        double travelled = speed * seconds;
        if (loop) {
            if (length == 0) {
                return corners[0];
            }
            travelled %= length;
        } else if (travelled >= length) {
            return corners[corners.length - 1];
        }
        // The last corner not beyond the distance travelled; corners of a zero-length leg share a distance.
        int found = Arrays.binarySearch(distances, travelled);
        int i = found >= 0 ? lastWithDistance(found) : -found - 2;
        if (i == corners.length - 1) {
            return corners[i];
        }
        double leg = distances[i + 1] - distances[i];
        return corners[i].towards(corners[i + 1], (travelled - distances[i]) / leg);
    }

    private int lastWithDistance(int index) {
        int i = index;
        while (i + 1 < distances.length && distances[i + 1] == distances[i]) {
            i++;
        }
        return i;
    }
}
