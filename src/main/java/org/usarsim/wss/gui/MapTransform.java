package org.usarsim.wss.gui;

import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;

/**
 * From world metres to the map's pixels: {@code scale} pixels a metre, the world's origin at
 * ({@code originX}, {@code originY}) on the screen, y pointing up in the world and down on the
 * screen. Immutable: zooming and panning make a new one.
 */
record MapTransform(double scale, double originX, double originY) {

    /** The smallest and largest scale a wheel can reach, pixels a metre. */
    static final double MIN_SCALE = 0.01;
    static final double MAX_SCALE = 10_000;
    /** The side of the square shown around a single point (one robot, say), metres. */
    static final double LEAST_SPAN = 10;

    /**
     * The transform that shows {@code world} whole and centred in a {@code width} by {@code height}
     * area less {@code margin} pixels on each side, with the same scale both ways.
     */
    static MapTransform fit(Rectangle2D world, int width, int height, int margin) {
        double spanX = Math.max(world.getWidth(), LEAST_SPAN);
        double spanY = Math.max(world.getHeight(), LEAST_SPAN);
        double usableX = Math.max(width - 2 * margin, 1);
        double usableY = Math.max(height - 2 * margin, 1);
        double scale = clamp(Math.min(usableX / spanX, usableY / spanY));
        return new MapTransform(scale, width / 2.0 - world.getCenterX() * scale, height / 2.0 + world.getCenterY() * scale);
    }

    Point2D toScreen(double x, double y) {
        return new Point2D.Double(originX + x * scale, originY - y * scale);
    }

    Point2D toWorld(double screenX, double screenY) {
        return new Point2D.Double((screenX - originX) / scale, (originY - screenY) / scale);
    }

    /** Zoomed by {@code factor} (above 1 nearer) about the screen point, which stays over the same place of the world. */
    MapTransform zoom(double factor, double screenX, double screenY) {
        double newScale = clamp(scale * factor);
        double applied = newScale / scale;
        return new MapTransform(newScale, screenX - (screenX - originX) * applied, screenY - (screenY - originY) * applied);
    }

    /** Moved by so many pixels, as when the map is dragged. */
    MapTransform pan(double dx, double dy) {
        return new MapTransform(scale, originX + dx, originY + dy);
    }

    private static double clamp(double scale) {
        return Math.max(MIN_SCALE, Math.min(MAX_SCALE, scale));
    }
}
