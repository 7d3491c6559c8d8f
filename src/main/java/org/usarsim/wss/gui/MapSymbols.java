package org.usarsim.wss.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Function;
import org.usarsim.wss.routes.RouteTable;

/**
 * The marks the map draws for the routes (docs/gui.md, "Routes on the map"): the base a dark
 * square around its dot, a robot cut off from the base a red ring crossed by a red bar, and what
 * the legend says of them (and of the picked route's band); the same drawing for a robot and for
 * its sample in the legend. Event thread.
 */
final class MapSymbols {

    static final Color BASE = new Color(0x20, 0x20, 0x28);
    static final Color CUT_OFF = new Color(0xD0, 0x10, 0x10);
    /** The side of the base's square and the cut-off ring's diameter, pixels: around the dot, clear of the name beside it. */
    static final int SIZE = MapPanel.DOT + 6;

    /** A mark drawn centred on a point. */
    interface Mark {
        void draw(Graphics2D g, double x, double y);
    }

    private MapSymbols() {
    }

    /** The base's square and each cut-off robot's ring, around their dots ({@code screen}: where a robot's dot is, null when not drawn). */
    static void paint(Graphics2D g, RouteTable routes, Function<String, Point2D> screen) {
        for (String robot : routes.robots()) {
            Point2D at = screen.apply(robot);
            if (at != null && robot.equals(routes.base())) {
                base(g, at.getX(), at.getY());
            } else if (at != null && routes.isCutOff(robot)) {
                cutOff(g, at.getX(), at.getY());
            }
        }
    }

    /**
     * The legend's entries for the routes, in order, each text with its mark: the base and the cut-off
     * robots when there is a base, the picked route's band when one is drawn.
     */
    static Map<String, Mark> legend(RouteTable routes, boolean routeDrawn) {
        Map<String, Mark> entries = new LinkedHashMap<>();
        if (routes.base() != null) {
            entries.put("base (" + routes.base() + ")", MapSymbols::base);
            entries.put("cut off from the base", MapSymbols::cutOff);
        }
        if (routeDrawn) {
            entries.put("picked route", MapSymbols::band);
        }
        return entries;
    }

    /** The base's square, centred on ({@code x}, {@code y}). */
    static void base(Graphics2D g, double x, double y) {
        g.setColor(BASE);
        g.setStroke(new BasicStroke(2));
        g.draw(new Rectangle2D.Double(x - SIZE / 2.0, y - SIZE / 2.0, SIZE, SIZE));
    }

    /** A cut-off robot's ring and bar, centred on ({@code x}, {@code y}). */
    static void cutOff(Graphics2D g, double x, double y) {
        g.setColor(CUT_OFF);
        g.setStroke(new BasicStroke(2.5f));
        double r = SIZE / 2.0;
        g.draw(new Ellipse2D.Double(x - r, y - r, SIZE, SIZE));
        double d = r * Math.sqrt(0.5);
        g.draw(new Line2D.Double(x - d, y + d, x + d, y - d));
    }

    /** A piece of the picked route's band, centred on ({@code x}, {@code y}): the legend's sample. */
    private static void band(Graphics2D g, double x, double y) {
        g.setColor(RoutePainter.BAND);
        g.setStroke(new BasicStroke(RoutePainter.WIDTH, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(x - 8, y, x + 8, y));
    }
}
