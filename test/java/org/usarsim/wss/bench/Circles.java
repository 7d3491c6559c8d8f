package org.usarsim.wss.bench;

/**
 * Where the CPU run's robots are: robot i on a circle of 30 m around its own centre (a grid of
 * 20 m), so that some pairs go in and out of range. {@code test/ros/latency_publisher.py} moves its
 * robots the same way.
 */
final class Circles {

    private Circles() {
    }

    /** Robot i's x and y at a time (s). */
    static double[] at(int i, double seconds) {
        double angle = seconds * 0.5 + i;
        return new double[] {(i % 10) * 20 + 30 * Math.cos(angle), (i / 10) * 20 + 30 * Math.sin(angle)};
    }
}
