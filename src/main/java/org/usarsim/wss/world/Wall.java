package org.usarsim.wss.world;

/**
 * A wall seen from above: a segment from (x1, y1) to (x2, y2), in metres, of any height, and its
 * material (empty: none given, the model's own attenuation).
 */
public record Wall(double x1, double y1, double x2, double y2, String material) {

    public Wall {
        material = material == null ? "" : material;
    }

    /** A wall of no given material. */
    public Wall(double x1, double y1, double x2, double y2) {
        this(x1, y1, x2, y2, "");
    }

    /** Whether the straight line on the floor between a and b crosses or touches this wall. */
    boolean blocks(Point a, Point b) {
        return Segments.meet(a.x(), a.y(), b.x(), b.y(), x1, y1, x2, y2);
    }
}
