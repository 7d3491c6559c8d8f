package org.usarsim.wss.model;

/**
 * A wall seen from above, as the simulator gives it: a segment from (x1, y1) to (x2, y2), in
 * metres, and its material (empty: none given; the map draws it in the plain wall colour).
 */
public record Wall(double x1, double y1, double x2, double y2, String material) {

    public Wall {
        material = material == null ? "" : material;
    }

    /** A wall of no given material (what every wall was before materials: plugins keep this constructor). */
    public Wall(double x1, double y1, double x2, double y2) {
        this(x1, y1, x2, y2, "");
    }
}
