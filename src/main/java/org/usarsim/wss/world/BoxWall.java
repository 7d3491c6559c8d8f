package org.usarsim.wss.world;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;

/**
 * A box of a Gazebo world seen from above: the convex outline of its corners on the floor (a
 * rotated rectangle for a box turned about z only), its name and its material. A line that
 * crosses or touches the outline anywhere, or starts or ends inside it, crosses this one wall,
 * whatever number of its edges it meets. Immutable.
 */
public final class BoxWall {

    private final String name;
    private final String material;
    /** The outline's corners, counter-clockwise; one or two corners for a degenerate box. */
    private final double[] xs;
    private final double[] ys;
    private final double minX;
    private final double minY;
    private final double maxX;
    private final double maxY;

    private BoxWall(String name, String material, double[] xs, double[] ys) {
        this.name = name;
        this.material = material == null ? "" : material;
        this.xs = xs;
        this.ys = ys;
        this.minX = Arrays.stream(xs).min().orElseThrow();
        this.maxX = Arrays.stream(xs).max().orElseThrow();
        this.minY = Arrays.stream(ys).min().orElseThrow();
        this.maxY = Arrays.stream(ys).max().orElseThrow();
    }

    /** The wall whose outline is the convex hull of these points on the floor ({x, y} each, at least one). */
    static BoxWall around(String name, String material, List<double[]> points) {
        List<double[]> sorted = new ArrayList<>(points);
        sorted.sort(Comparator.<double[]>comparingDouble(p -> p[0]).thenComparingDouble(p -> p[1]));
        // Andrew's monotone chain: the lower hull, then the upper, counter-clockwise.
        double[][] hull = new double[2 * sorted.size() + 1][];
        int k = 0;
        for (double[] p : sorted) {
            while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) {
                k--;
            }
            hull[k++] = p;
        }
        for (int i = sorted.size() - 2, lower = k + 1; i >= 0; i--) {
            double[] p = sorted.get(i);
            while (k >= lower && cross(hull[k - 2], hull[k - 1], p) <= 0) {
                k--;
            }
            hull[k++] = p;
        }
        int corners = Math.max(1, k - 1);
        double[] xs = new double[corners];
        double[] ys = new double[corners];
        for (int i = 0; i < corners; i++) {
            xs[i] = hull[i][0];
            ys[i] = hull[i][1];
        }
        return new BoxWall(name, material, xs, ys);
    }

    private static double cross(double[] o, double[] a, double[] b) {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    }

    /** The model, link and collision the box comes from ({@code model::link::collision}). */
    public String name() {
        return name;
    }

    /** The material the rules gave it; empty for none. */
    public String material() {
        return material;
    }

    /** The outline's edges, each a wall of this material: what the map draws and a recording keeps. */
    public List<Wall> edges() {
        List<Wall> edges = new ArrayList<>(xs.length);
        for (int i = 0; i < xs.length; i++) {
            int j = (i + 1) % xs.length;
            if (xs.length > 2 || i == 0) {
                edges.add(new Wall(xs[i], ys[i], xs[j], ys[j], material));
            }
        }
        return edges;
    }

    double minX() {
        return minX;
    }

    double minY() {
        return minY;
    }

    double maxX() {
        return maxX;
    }

    double maxY() {
        return maxY;
    }

    /** Whether the line on the floor from (ax, ay) to (bx, by) crosses, touches or lies in the outline. */
    boolean blocks(double ax, double ay, double bx, double by) {
        if (Math.max(ax, bx) < minX - Segments.TOUCH || Math.min(ax, bx) > maxX + Segments.TOUCH
                || Math.max(ay, by) < minY - Segments.TOUCH || Math.min(ay, by) > maxY + Segments.TOUCH) {
            return false;
        }
        if (beside(ax, ay, bx, by)) {
            return false;
        }
        if (inside(ax, ay)) {
            return true;
        }
        // A proper crossing of an edge first (cheap); then touching, the dearer test.
        for (int i = 0; i < xs.length; i++) {
            int j = (i + 1) % xs.length;
            if (Segments.cross(ax, ay, bx, by, xs[i], ys[i], xs[j], ys[j])) {
                return true;
            }
        }
        for (int i = 0; i < xs.length; i++) {
            int j = (i + 1) % xs.length;
            if (Segments.meet(ax, ay, bx, by, xs[i], ys[i], xs[j], ys[j])) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether every corner lies more than {@link Segments#TOUCH} to the same side of the line
     * through a and b: then the outline cannot meet the segment. The cheap test that rejects most
     * of the boxes near a line; never true for a line of length 0.
     */
    private boolean beside(double ax, double ay, double bx, double by) {
        double dx = bx - ax;
        double dy = by - ay;
        double margin = Segments.TOUCH * Math.sqrt(dx * dx + dy * dy);
        boolean left = true;
        boolean right = true;
        for (int i = 0; i < xs.length && (left || right); i++) {
            double side = dx * (ys[i] - ay) - dy * (xs[i] - ax);
            left &= side > margin;
            right &= side < -margin;
        }
        return left || right;
    }

    /** Whether the point lies inside the outline (a line with an end inside crosses it, if no edge). */
    private boolean inside(double px, double py) {
        if (xs.length < 3) {
            return false;
        }
        for (int i = 0; i < xs.length; i++) {
            int j = (i + 1) % xs.length;
            if ((xs[j] - xs[i]) * (py - ys[i]) - (ys[j] - ys[i]) * (px - xs[i]) < 0) {
                return false;
            }
        }
        return true;
    }

    @Override
    public String toString() {
        return "BoxWall[" + name + ", " + material + ", " + edges() + "]";
    }
}
