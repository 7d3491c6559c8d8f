package org.usarsim.wss.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Shape;
import java.awt.Stroke;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Point2D;
import java.awt.geom.QuadCurve2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.shaping.Bitrate;

/**
 * One painting of the {@link MapPanel}'s map: the grid, the walls, the selected robot's range, the
 * pairs' lines with their labels (never over a robot's name or dot, nor over another label: a
 * {@link LabelPlacer}), the robots, the legend and the scale, from the {@link MapData} and the
 * {@link MapTransform} it is given. Event thread.
 */
final class MapPainter {

    private static final int DOT = MapPanel.DOT;
    static final Color WALL = new Color(0x40, 0x40, 0x48);
    private static final Color ROBOT = new Color(0x1F, 0x4E, 0x9A);
    private static final Color SELECTED = new Color(0xD0, 0x40, 0x20);
    private static final Color RANGE = new Color(0x1F, 0x4E, 0x9A);
    private static final Color GRID = new Color(0xEE, 0xEE, 0xF2);

    private final int width;
    private final int height;
    private final Font font;
    private final Color background;
    private final String selected;
    /** The picked route drawn over the lines ({@link RoutePainter}); null: none. */
    private final DrawnRoute route;

    /**
     * A painting of a canvas of this size, font and background, {@code selected} the robot whose
     * range is drawn (null: none), {@code route} the picked route drawn over the lines (null: none).
     */
    MapPainter(int width, int height, Font font, Color background, String selected, DrawnRoute route) {
        this.width = width;
        this.height = height;
        this.font = font;
        this.background = background;
        this.selected = selected;
        this.route = route;
    }

    /** Paints {@code shown} with {@code t}; where it put the names and the labels. */
    LabelPlacer paint(Graphics2D g, MapTransform t, MapData shown) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(background);
        g.fillRect(0, 0, width, height);
        double step = gridStep(t.scale());
        paintGrid(g, t, step);
        paintWalls(g, t, shown);
        LabelPlacer labels = new LabelPlacer(new Rectangle2D.Double(0, 0, width, height));
        nameBoxes(g, t, shown, labels);
        paintRange(g, t, shown, labels);
        paintLines(g, t, shown, labels);
        paintRobots(g, t, shown);
        paintLegend(g, t, step, shown);
        if (shown.robots().stream().noneMatch(robot -> robot.position() != null)) {
            g.setColor(Color.GRAY);
            String text = shown.robots().isEmpty() ? "No robots" : "No robot has a position (the model gives none)";
            g.drawString(text, (width - g.getFontMetrics().stringWidth(text)) / 2, height / 2);
        }
        return labels;
    }

    /** Where the robot's dot is; null when it has no position or is not shown. */
    static Point2D screenOf(MapTransform t, MapData shown, String robot) {
        MapData.Robot known = shown.robot(robot);
        return known == null || known.position() == null ? null : t.toScreen(known.position().x(), known.position().y());
    }

    private void paintGrid(Graphics2D g, MapTransform t, double step) {
        Point2D from = t.toWorld(0, height);
        Point2D to = t.toWorld(width, 0);
        g.setColor(GRID);
        g.setStroke(new BasicStroke(1));
        for (double x = Math.floor(from.getX() / step) * step; x <= to.getX(); x += step) {
            int sx = (int) Math.round(t.toScreen(x, 0).getX());
            g.drawLine(sx, 0, sx, height);
        }
        for (double y = Math.floor(from.getY() / step) * step; y <= to.getY(); y += step) {
            int sy = (int) Math.round(t.toScreen(0, y).getY());
            g.drawLine(0, sy, width, sy);
        }
    }

    private void paintWalls(Graphics2D g, MapTransform t, MapData shown) {
        g.setStroke(new BasicStroke(3, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        for (Wall wall : shown.walls()) {
            g.setColor(MapColours.wall(wall.material()));
            g.draw(new Line2D.Double(t.toScreen(wall.x1(), wall.y1()), t.toScreen(wall.x2(), wall.y2())));
        }
    }

    private void paintRange(Graphics2D g, MapTransform t, MapData shown, LabelPlacer labels) {
        MapData.Robot robot = selected != null ? shown.robot(selected) : null;
        if (robot == null || robot.position() == null || !(robot.range() > 0) || Double.isInfinite(robot.range())) {
            return;
        }
        Point2D at = t.toScreen(robot.position().x(), robot.position().y());
        double r = robot.range() * t.scale();
        Ellipse2D circle = new Ellipse2D.Double(at.getX() - r, at.getY() - r, 2 * r, 2 * r);
        g.setColor(new Color(RANGE.getRed(), RANGE.getGreen(), RANGE.getBlue(), 24));
        g.fill(circle);
        g.setColor(new Color(RANGE.getRed(), RANGE.getGreen(), RANGE.getBlue(), 160));
        g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {6, 4}, 0));
        g.draw(circle);
        // Beside the robot's dot: the circle itself may lie beyond the canvas.
        String label = String.format(Locale.ROOT, "range %.1f m", robot.range());
        g.setFont(font.deriveFont(Font.PLAIN, 11f));
        FontMetrics metrics = g.getFontMetrics();
        // Under the name first; else left of the dot, below or above it: never over another robot's name.
        double width = metrics.stringWidth(label) + 4;
        double top = at.getY() + 2 * DOT - metrics.getAscent();
        double above = at.getY() - DOT / 2.0 - metrics.getAscent() - metrics.getHeight() - 2;
        Rectangle2D box = labels.place(List.of(new Point2D.Double(at.getX() + DOT - 2, top),
                new Point2D.Double(at.getX() - DOT - width, top), new Point2D.Double(at.getX() + DOT - 2, above),
                new Point2D.Double(at.getX() - DOT - width, above)), width, metrics.getHeight(), label, null);
        if (box != null) {
            label(g, label, box.getX() + 2, box.getY() + metrics.getAscent());
        }
    }

    /** The robots' names' and dots' boxes, taken first: a pair's label never lies over a name or a dot. */
    private void nameBoxes(Graphics2D g, MapTransform t, MapData shown, LabelPlacer labels) {
        FontMetrics metrics = g.getFontMetrics(font.deriveFont(Font.BOLD, 12f));
        for (MapData.Robot robot : shown.robots()) {
            if (robot.position() != null) {
                Point2D at = t.toScreen(robot.position().x(), robot.position().y());
                labels.take(nameBox(at, robot.name(), metrics));
                labels.block(dotBox(at));
            }
        }
    }

    /** The square a robot's dot is drawn in. */
    static Rectangle2D dotBox(Point2D at) {
        return new Rectangle2D.Double(at.getX() - DOT / 2.0, at.getY() - DOT / 2.0, DOT, DOT);
    }

    /**
     * The lines first, then their labels, over every line (on their light patch) and off the
     * others' lines where they can be. A line that would run through another robot's dot (three
     * robots in a line) is drawn as a curve bowed around it, its label along the curve. While a
     * route is drawn, the other lines are faded and only its hops are labelled ({@link RoutePainter}).
     */
    private void paintLines(Graphics2D g, MapTransform t, MapData shown, LabelPlacer labels) {
        Map<MapData.Line, List<Point2D>> drawn = new LinkedHashMap<>();
        for (MapData.Line line : shown.lines()) {
            Point2D a = screenOf(t, shown, line.first());
            Point2D b = screenOf(t, shown, line.second());
            if (a == null || b == null) {
                continue;
            }
            Point2D control = control(a, b, t, shown, line);
            Shape path = control == null ? new Line2D.Double(a, b) : new QuadCurve2D.Double(a.getX(), a.getY(), control.getX(),
                    control.getY(), b.getX(), b.getY());
            Color colour = MapColours.of(line, shown.cutoff());
            g.setColor(route == null || onRoute(line) ? colour : RoutePainter.faded(colour));
            g.setStroke(lineStroke(MapLineWidth.of(line), line.forced()));
            g.draw(path);
            labels.line(path);
            drawn.put(line, List.of(a, control == null ? middle(a, b) : control, b));
        }
        if (route != null) { // over the lines, its hops' labels first
            RoutePainter.paint(g, route, (a, b) -> curve(drawn, shown.line(a, b), a), labels, font);
        }
        List<Shape> paths = labels.lines();
        g.setFont(font.deriveFont(Font.PLAIN, 10f));
        FontMetrics metrics = g.getFontMetrics();
        int i = 0;
        for (Map.Entry<MapData.Line, List<Point2D>> entry : drawn.entrySet()) {
            Shape own = paths.get(i++);
            String text = route != null ? "" : lineLabel(entry.getKey()); // a route drawn: its hops' labels only
            if (!text.isEmpty()) {
                List<Point2D> abc = entry.getValue();
                double width = metrics.stringWidth(text) + 4;
                Rectangle2D box = labels.place(LabelPlacer.alongCurve(abc.get(0), abc.get(1), abc.get(2), width, metrics.getHeight()),
                        width, metrics.getHeight(), text, own);
                if (box != null) { // no free place: left out, not drawn over another (the Link statistics have it)
                    g.setColor(MapColours.of(entry.getKey(), shown.cutoff()));
                    label(g, text, box.getX() + 2, box.getY() + metrics.getAscent());
                }
            }
        }
    }

    /** The line as drawn from robot {@code from}: start, control point, end; null when it is not drawn. */
    private static List<Point2D> curve(Map<MapData.Line, List<Point2D>> drawn, MapData.Line line, String from) {
        List<Point2D> abc = line == null ? null : drawn.get(line);
        return abc == null || line.first().equals(from) ? abc : List.of(abc.get(2), abc.get(1), abc.get(0));
    }

    /** Whether the pair is a hop of the route drawn. */
    private boolean onRoute(MapData.Line line) {
        return route != null && route.hops().stream().anyMatch(hop -> hop.from().equals(line.first()) && hop.to().equals(line.second())
                || hop.from().equals(line.second()) && hop.to().equals(line.first()));
    }

    /** How far a line bowed around a robot in its way passes from the straight one, at most, in pixels. */
    private static final double BOW = 4 * DOT;

    /**
     * The control point of the curve the pair's line is drawn as when another robot's dot lies on
     * the straight line between the two (so that the line is not hidden under the two shorter
     * ones, nor its label left floating): to the left of a to b, bowing the curve's middle half
     * of {@link #BOW} (or a fifth of its length) off the straight line; null when none is in the way.
     */
    private static Point2D control(Point2D a, Point2D b, MapTransform t, MapData shown, MapData.Line line) {
        Line2D straight = new Line2D.Double(a, b);
        boolean inTheWay = shown.robots().stream().filter(robot -> robot.position() != null)
                .filter(robot -> !robot.name().equals(line.first()) && !robot.name().equals(line.second()))
                .anyMatch(robot -> straight.ptSegDist(t.toScreen(robot.position().x(), robot.position().y())) < DOT);
        double length = a.distance(b);
        if (!inTheWay || length == 0) {
            return null;
        }
        // The curve's middle is half as far off the straight line as its control point.
        double off = 2 * Math.min(BOW, length / 5);
        Point2D middle = middle(a, b);
        return new Point2D.Double(middle.getX() + (a.getY() - b.getY()) / length * off, middle.getY() + (b.getX() - a.getX()) / length * off);
    }

    private static Point2D middle(Point2D a, Point2D b) {
        return new Point2D.Double((a.getX() + b.getX()) / 2, (a.getY() + b.getY()) / 2);
    }

    /** Text in the current colour and font on a light patch, legible over lines and walls. */
    static void label(Graphics2D g, String text, double x, double y) {
        FontMetrics metrics = g.getFontMetrics();
        Color ink = g.getColor();
        g.setColor(new Color(255, 255, 255, 210));
        g.fillRect((int) x - 2, (int) y - metrics.getAscent(), metrics.stringWidth(text) + 4, metrics.getHeight());
        g.setColor(ink);
        g.drawString(text, (float) x, (float) y);
    }

    private Stroke lineStroke(float width, boolean dashed) {
        return dashed ? new BasicStroke(width, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {8, 6}, 0)
                : new BasicStroke(width);
    }

    private void paintRobots(Graphics2D g, MapTransform t, MapData shown) {
        g.setFont(font.deriveFont(Font.BOLD, 12f));
        for (MapData.Robot robot : shown.robots()) {
            Position p = robot.position();
            if (p == null) {
                continue;
            }
            Point2D at = t.toScreen(p.x(), p.y());
            boolean isSelected = robot.name().equals(selected);
            g.setColor(isSelected ? SELECTED : ROBOT);
            g.fill(new Ellipse2D.Double(at.getX() - DOT / 2.0, at.getY() - DOT / 2.0, DOT, DOT));
            // On a light patch, as the labels: a wall or a line under the name does not strike it through.
            label(g, robot.name(), at.getX() + DOT, at.getY() - DOT / 2.0);
        }
        MapSymbols.paint(g, shown.routes(), robot -> screenOf(t, shown, robot)); // after the names' patches: never under one
    }

    /** Where a robot's name is drawn: right of its dot, its baseline half a dot above. */
    private Rectangle2D nameBox(Point2D at, String name, FontMetrics metrics) {
        return new Rectangle2D.Double(at.getX() + DOT, at.getY() - DOT / 2.0 - metrics.getAscent(),
                metrics.stringWidth(name), metrics.getHeight());
    }

    private void paintLegend(Graphics2D g, MapTransform t, double step, MapData shown) {
        g.setFont(font.deriveFont(Font.PLAIN, 11f));
        FontMetrics metrics = g.getFontMetrics();
        int x = 10;
        int y = height - 12;
        List<LegendEntry> entries = new ArrayList<>(List.of(
                new LegendEntry(MapColours.STRONG, false, MapLineWidth.UNSHAPED, "up"),
                new LegendEntry(MapColours.NEAR, false, MapLineWidth.UNSHAPED,
                        "within " + (int) MapColours.NEAR_DB + " dB of the cutoff"),
                new LegendEntry(MapColours.BROKEN, false, MapLineWidth.UNSHAPED, "broken / forced down"),
                new LegendEntry(Color.DARK_GRAY, true, MapLineWidth.UNSHAPED, "forced")));
        if (shown.lines().stream().anyMatch(line -> line.rate() > 0)) { // links shaped: what the widths mean
            entries.add(new LegendEntry(Color.DARK_GRAY, false, MapLineWidth.THINNEST, Bitrate.format(MapLineWidth.LOWEST)));
            entries.add(new LegendEntry(Color.DARK_GRAY, false, MapLineWidth.THICKEST, Bitrate.format(MapLineWidth.TOP)));
        }
        shown.walls().stream().map(Wall::material).filter(m -> !m.isEmpty()).distinct() // walls of materials: their colours
                .forEach(m -> entries.add(new LegendEntry(MapColours.wall(m), false, 3, m)));
        MapSymbols.legend(shown.routes(), route != null).forEach((text, mark) -> entries.add(new LegendEntry(null, false, 0, text, mark)));
        // The scale's room at the right: the legend wraps onto a row above rather than run into it.
        int scaleLeft = width - 12 - (int) Math.round(step * t.scale()) - 12;
        for (LegendEntry entry : entries) {
            int entryWidth = 30 + metrics.stringWidth(entry.text());
            if (x > 10 && x + entryWidth > scaleLeft) {
                x = 10;
                y -= metrics.getHeight() + 4;
            }
            if (entry.mark() != null) {
                entry.mark().draw(g, x + 12, y - 4);
            } else {
                g.setColor(entry.colour());
                g.setStroke(lineStroke(entry.width(), entry.dashed()));
                g.drawLine(x, y - 4, x + 24, y - 4);
            }
            g.setColor(Color.DARK_GRAY);
            g.drawString(entry.text(), x + 30, y);
            x += 40 + metrics.stringWidth(entry.text());
        }
        // The scale: one grid step, on the bottom row.
        y = height - 12;
        int pixels = (int) Math.round(step * t.scale());
        int right = width - 12;
        g.setStroke(new BasicStroke(2));
        g.drawLine(right - pixels, y - 4, right, y - 4);
        g.drawLine(right - pixels, y - 8, right - pixels, y);
        g.drawLine(right, y - 8, right, y);
        String label = (step >= 1 ? String.valueOf((long) step) : String.valueOf(step)) + " m";
        g.drawString(label, right - pixels / 2 - metrics.stringWidth(label) / 2, y - 10);
    }

    /** A line of the legend: a sample of a line drawn so (or a mark drawn around a dot), and what it means. */
    private record LegendEntry(Color colour, boolean dashed, float width, String text, MapSymbols.Mark mark) {

        LegendEntry(Color colour, boolean dashed, float width, String text) {
            this(colour, dashed, width, text, null);
        }
    }

    /**
     * The text at the middle of a pair's line: the model's strength ("-71.3 dBm", none when it
     * has none), then with links shaped the rate of a pair that is up ("54 Mbit/s"), or the state
     * of a pair that is not ("broken", "forced down"), as the Link statistics' State says it.
     */
    static String lineLabel(MapData.Line line) {
        List<String> parts = new ArrayList<>();
        if (!Double.isNaN(line.strength()) && !Double.isInfinite(line.strength())) {
            parts.add(String.format(Locale.ROOT, "%.1f dBm", line.strength()));
        }
        if (!line.state().isUp()) {
            parts.add(line.state().text());
        } else if (line.rate() > 0) {
            parts.add(Bitrate.format(line.rate()));
        }
        return String.join(", ", parts);
    }

    /** A round number of metres (1, 2 or 5 times a power of ten) that is 50 to 125 pixels at this scale. */
    static double gridStep(double scale) {
        double metres = 60 / scale;
        double power = Math.pow(10, Math.floor(Math.log10(metres)));
        for (double m : new double[] {1, 2, 5, 10}) {
            if (m * power >= metres) {
                return m * power;
            }
        }
        return 10 * power;
    }
}
