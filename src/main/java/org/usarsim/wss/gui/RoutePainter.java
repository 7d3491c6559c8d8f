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
 * otherwise); the map fades the other lines and leaves their labels out meanwhile. Event thread.
 */
final class RoutePainter {

    /** The band, translucent over the lines under it. */
    static final Color BAND = new Color(0x7A, 0x2C, 0xC8, 150);
    /** The hops' labels' ink and the legend's sample. */
    static final Color INK = new Color(0x5A, 0x1E, 0x96);
    static final float WIDTH = 10;

    private RoutePainter() {
    }

    /** A hop label's candidate corners along its hop, as a pair label's ({@link LabelPlacer#alongCurve}) but clear of the band. */
    private static List<Point2D> beside(List<Point2D> abc, double width, double height) {
        double clear = WIDTH / 2 + 1;
        return LabelPlacer.alongCurve(abc.get(0), abc.get(1), abc.get(2), width + 2 * clear, height + 2 * clear).stream()
                .map(corner -> (Point2D) new Point2D.Double(corner.getX() + clear, corner.getY() + clear)).toList();
    }

    /** A line off the route while one is drawn: its colour, faded, so that the route stands out. */
    static Color faded(Color colour) {
        return new Color(colour.getRed(), colour.getGreen(), colour.getBlue(), 60);
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
        BasicStroke stroke = new BasicStroke(WIDTH, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND);
        g.setStroke(stroke);
        g.draw(band);
        labels.line(stroke.createStrokedShape(band)); // the hops' labels keep off the band where they can
        g.setFont(font.deriveFont(Font.BOLD, 11f));
        FontMetrics metrics = g.getFontMetrics();
        for (Hop hop : route.hops()) {
            List<Point2D> abc = curve.apply(hop.from(), hop.to());
            String text = RouteText.hopLabel(hop, route.shaped());
            if (abc != null && !text.isEmpty()) {
                double width = metrics.stringWidth(text) + 4;
                Rectangle2D box = labels.place(beside(abc, width, metrics.getHeight()), width, metrics.getHeight(), text, null);
                if (box != null) {
                    g.setColor(INK);
                    MapPainter.label(g, text, box.getX() + 2, box.getY() + metrics.getAscent());
                }
            }
        }
    }
}
