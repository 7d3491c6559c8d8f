package org.usarsim.wss.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.List;
import java.util.function.BiFunction;
import org.usarsim.wss.routes.Hop;

/**
 * The picked route on the map (docs/gui.md, "A route on the map"): a thick translucent band along
 * its hops' lines as drawn (a curve where a pair's line bows around a robot), over the lines and
 * under the labels and the robots, and each hop's label (its rate with links shaped, its strength
 * otherwise) placed before the pairs' labels, so that it gets the best free place. Event thread.
 */
final class RoutePainter {

    /** The band, translucent over the lines under it. */
    static final Color BAND = new Color(0x8E, 0x3C, 0xD8, 130);
    /** The hops' labels' ink and the legend's sample. */
    static final Color INK = new Color(0x5A, 0x1E, 0x96);
    static final float WIDTH = 10;

    private RoutePainter() {
    }

    /**
     * Draws {@code route}'s band and places and draws its hops' labels; {@code curve} gives the
     * pair's line as drawn from one robot to the other, start, control point and end (null when
     * it is not drawn: a robot without a position).
     */
    static void paint(Graphics2D g, DrawnRoute route, BiFunction<String, String, List<Point2D>> curve, LabelPlacer labels, Font font) {
        Path2D band = new Path2D.Double();
        boolean open = false;
        for (Hop hop : route.hops()) {
            List<Point2D> abc = curve.apply(hop.from(), hop.to());
            if (abc == null) {
                open = false;
                continue;
            }
            if (!open) {
                band.moveTo(abc.get(0).getX(), abc.get(0).getY());
                open = true;
            }
            band.quadTo(abc.get(1).getX(), abc.get(1).getY(), abc.get(2).getX(), abc.get(2).getY());
        }
        g.setColor(BAND);
        g.setStroke(new BasicStroke(WIDTH, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(band);
        g.setFont(font.deriveFont(Font.BOLD, 11f));
        FontMetrics metrics = g.getFontMetrics();
        for (Hop hop : route.hops()) {
            List<Point2D> abc = curve.apply(hop.from(), hop.to());
            String text = RouteText.hopLabel(hop, route.shaped());
            if (abc != null && !text.isEmpty()) {
                double width = metrics.stringWidth(text) + 4;
                Rectangle2D box = labels.place(LabelPlacer.alongCurve(abc.get(0), abc.get(1), abc.get(2), width, metrics.getHeight()),
                        width, metrics.getHeight(), text, null);
                if (box != null) {
                    g.setColor(INK);
                    MapPainter.label(g, text, box.getX() + 2, box.getY() + metrics.getAscent());
                }
            }
        }
    }
}
