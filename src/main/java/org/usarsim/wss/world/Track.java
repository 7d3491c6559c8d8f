package org.usarsim.wss.world;

import java.util.List;

/**
 * A robot's timed points ({@code at} lines of the world file, docs/world.md): at each point's time
 * it is at that point, in between it moves in a straight line at the speed that takes it from one
 * to the next in the time between them. Before the first point's time it is at its start; after
 * the last it stays at the last point. A recording exported to a world file (docs/replay.md) is a
 * track per robot.
 */
final class Track implements Motion {

    /** One point of a track: where, and when in seconds from the world's start. */
    record TimedPoint(double seconds, Point point) {
    }

    private final Point start;
    private final double[] times;
    private final Point[] points;

    /** @throws IllegalArgumentException unless there is a point and the times grow strictly, from 0 on */
    Track(Point start, List<TimedPoint> timed) {
        if (timed.isEmpty()) {
            throw new IllegalArgumentException("a track with no point");
        }
        this.start = start;
        this.times = new double[timed.size()];
        this.points = new Point[timed.size()];
        for (int i = 0; i < times.length; i++) {
            times[i] = timed.get(i).seconds();
            points[i] = timed.get(i).point();
            if (!(times[i] >= 0) || Double.isInfinite(times[i]) || (i > 0 && !(times[i] > times[i - 1]))) {
                throw new IllegalArgumentException("times must grow from 0 on: " + timed);
            }
        }
    }

    @Override
    public Point at(double seconds) {
        if (seconds < times[0]) {
            return start;
        }
        int last = times.length - 1;
        if (seconds >= times[last]) {
            return points[last];
        }
        int low = 0;
        int high = last;
        while (high - low > 1) { // times[low] <= seconds < times[high]
            int middle = (low + high) >>> 1;
            if (times[middle] <= seconds) {
                low = middle;
            } else {
                high = middle;
            }
        }
        return points[low].towards(points[high], (seconds - times[low]) / (times[high] - times[low]));
    }
}
