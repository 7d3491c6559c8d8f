package org.usarsim.wss.gui;

import java.awt.BasicStroke;
import java.awt.Shape;
import java.awt.geom.Line2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.List;

/**
 * Where the map's labels go so that no two boxes overlap (issue 26): the boxes taken so far (the
 * robots' names first), and for each new label the first of its candidate places that overlaps
 * none and lies wholly on the map (not cut by its edge). A label with no free place is left out: the
 * Link statistics say the same. Pure geometry, one per painting.
 */
final class LabelPlacer {

    private final Rectangle2D within;

    private final List<Rectangle2D> taken = new ArrayList<>();
    private final List<Rectangle2D> names = new ArrayList<>();
    private final List<Rectangle2D> placed = new ArrayList<>();
    private final List<String> texts = new ArrayList<>();
    /** The pairs' lines as drawn (a segment, or a curve around a robot in the way) and the outline each covers. */
    private final List<Shape> lines = new ArrayList<>();
    private final List<Shape> outlines = new ArrayList<>();
    private int leftOut;

    /** Places labels inside {@code within}: the canvas. */
    LabelPlacer(Rectangle2D within) {
        this.within = within;
    }

    /** Takes a box no label may lie over that is not a name: a robot's dot. */
    void block(Rectangle2D box) {
        taken.add(box);
    }

    /** Takes a box that is drawn whatever: a robot's name. */
    void take(Rectangle2D box) {
        taken.add(box);
        names.add(box);
    }

    /** A pair's line as drawn, a segment or a curve: labels other than its own keep off it where they can. */
    void line(Shape drawn) {
        lines.add(drawn);
        outlines.add(drawn instanceof Line2D ? drawn : new BasicStroke(1).createStrokedShape(drawn));
    }

    /** The pairs' lines as drawn, in order. */
    List<Shape> lines() {
        return List.copyOf(lines);
    }

    private boolean crossed(Rectangle2D box, Shape own) {
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i) != own && outlines.get(i).intersects(box)) {
                return true;
            }
        }
        return false;
    }

    /**
     * The first box of {@code width} x {@code height} whose top left is one of {@code corners}
     * (in order of preference), lies inside the canvas, overlaps no box taken and is crossed by no
     * line but {@code own} (the label's own line, or null); failing that, the first that only lies
     * inside and overlaps nothing (the map draws labels over the lines, on a light patch). Taken
     * for {@code text}; null when every one is cut or overlaps.
     */
    Rectangle2D place(List<Point2D> corners, double width, double height, String text, Shape own) {
        Rectangle2D crossed = null;
        for (Point2D corner : corners) {
            Rectangle2D box = new Rectangle2D.Double(corner.getX(), corner.getY(), width, height);
            if (within.contains(box) && taken.stream().noneMatch(box::intersects)) {
                if (!crossed(box, own)) {
                    return take(box, text);
                }
                crossed = crossed == null ? box : crossed;
            }
        }
        if (crossed != null) {
            return take(crossed, text);
        }
        leftOut++;
        return null;
    }

    private Rectangle2D take(Rectangle2D box, String text) {
        taken.add(box);
        placed.add(box);
        texts.add(text);
        return box;
    }

    /** The boxes taken so far, in order. */
    List<Rectangle2D> taken() {
        return List.copyOf(taken);
    }

    /** The boxes taken whatever (the robots' names), in order. */
    List<Rectangle2D> names() {
        return List.copyOf(names);
    }

    /** The labels' boxes {@link #place} found a free place for, in order. */
    List<Rectangle2D> placed() {
        return List.copyOf(placed);
    }

    /** The texts of the labels {@link #place} found a free place for, in the order of {@link #placed}. */
    List<String> texts() {
        return List.copyOf(texts);
    }

    /** How many labels {@link #place} left out for want of a free place. */
    int leftOut() {
        return leftOut;
    }

    /**
     * A pair label's candidate corners along the segment from {@code a} to {@code b}: beside its
     * middle first, then beside points a third and two thirds along, each above and below.
     */
    static List<Point2D> alongLine(Point2D a, Point2D b, double width, double height) {
        return alongCurve(a, new Point2D.Double((a.getX() + b.getX()) / 2, (a.getY() + b.getY()) / 2), b, width, height);
    }

    /**
     * As {@link #alongLine}, along the quadratic curve from {@code a} to {@code b} with control
     * point {@code control} (a straight line when it is the middle).
     */
    static List<Point2D> alongCurve(Point2D a, Point2D control, Point2D b, double width, double height) {
        List<Point2D> corners = new ArrayList<>();
        for (double along : new double[] {0.5, 1 / 3.0, 2 / 3.0, 0.25, 0.75}) {
            double u = 1 - along;
            double x = u * u * a.getX() + 2 * u * along * control.getX() + along * along * b.getX();
            double y = u * u * a.getY() + 2 * u * along * control.getY() + along * along * b.getY();
            corners.add(new Point2D.Double(x + 4, y - 4 - height));
            corners.add(new Point2D.Double(x + 4, y + 4));
            corners.add(new Point2D.Double(x - 4 - width, y - 4 - height));
            corners.add(new Point2D.Double(x - 4 - width, y + 4));
        }
        return corners;
    }
}
