package org.usarsim.wss.gui;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.util.List;
import javax.swing.JFrame;
import javax.swing.JTabbedPane;
import org.usarsim.wss.model.Position;

/** Reads the main window's map from a test of another package: everything on the event thread. */
public final class MapProbe {

    private final JFrame frame;
    private final MapPanel map;

    private MapProbe(JFrame frame, MapPanel map) {
        this.frame = frame;
        this.map = map;
    }

    /** The map of this window. */
    public static MapProbe of(JFrame frame) {
        return new MapProbe(frame, edt(() -> Gui.all(frame.getContentPane(), MapPanel.class).get(0)));
    }

    /** Brings the "Map" tab to the front. */
    public void showMap() {
        Gui.run(() -> {
            JTabbedPane tabs = Gui.find(frame.getContentPane(), JTabbedPane.class, "tabs");
            tabs.setSelectedIndex(tabs.indexOfTab("Map"));
        });
    }

    /** Whether the map shows these robots, every one with a position, and a line for every pair of them. */
    public boolean shows(List<String> robots) {
        return edt(() -> {
            MapData data = map.data();
            return data.robots().stream().filter(robot -> robot.position() != null).map(MapData.Robot::name).sorted().toList()
                    .equals(robots.stream().sorted().toList())
                    && data.lines().size() == robots.size() * (robots.size() - 1) / 2;
        });
    }

    /** The model position the map holds for the robot; null when none. */
    public Position position(String robot) {
        return edt(() -> {
            MapData.Robot known = map.data().robot(robot);
            return known == null ? null : known.position();
        });
    }

    /** Where the robot's dot is drawn, taken back to the world through the map's transform (metres). */
    public Point2D dotInWorld(String robot) {
        return edt(() -> {
            Point2D screen = map.screenOf(robot);
            return screen == null ? null : map.transform().toWorld(screen.getX(), screen.getY());
        });
    }

    /** Whether the robot's dot lies inside the canvas. */
    public boolean dotOnCanvas(String robot) {
        return edt(() -> {
            Point2D screen = map.screenOf(robot);
            return screen != null && map.canvas().contains((int) screen.getX(), (int) screen.getY());
        });
    }

    /** The colour the rule gives the line of the pair (names in any order). */
    public Color lineColour(String a, String b) {
        return edt(() -> MapColours.of(line(a, b), map.data().cutoff()));
    }

    /**
     * The colour painted a {@code fraction} of the way along the pair's line, the canvas painted
     * afresh: of the 3 x 3 pixels there, the one least like the white ground (antialiasing blends
     * the edges of a line with the ground; its core is its colour).
     */
    public Color pixelAlong(String a, String b, double fraction) {
        return edt(() -> {
            BufferedImage image = paintCanvas();
            Point2D from = map.screenOf(a);
            Point2D to = map.screenOf(b);
            int x = (int) Math.round(from.getX() + (to.getX() - from.getX()) * fraction);
            int y = (int) Math.round(from.getY() + (to.getY() - from.getY()) * fraction);
            Color inked = Color.WHITE;
            for (int dx = -1; dx <= 1; dx++) {
                for (int dy = -1; dy <= 1; dy++) {
                    Color pixel = new Color(image.getRGB(x + dx, y + dy));
                    if (pixel.getRed() + pixel.getGreen() + pixel.getBlue() < inked.getRed() + inked.getGreen() + inked.getBlue()) {
                        inked = pixel;
                    }
                }
            }
            return inked;
        });
    }

    /** The width the rule gives the pair's line (names in any order), in pixels. */
    public float lineWidth(String a, String b) {
        return edt(() -> MapLineWidth.of(line(a, b)));
    }

    /** The pair's link rate the map holds (bit/s; 0: none, links not shaped). */
    public long rate(String a, String b) {
        return edt(() -> line(a, b).rate());
    }

    /**
     * How wide the pair's line is painted a {@code fraction} of the way along it, the canvas
     * painted afresh: the pixels across the line (along its normal, one per pixel of distance)
     * that are inked more than half with the line's colour, counted outwards from its middle as far
     * as they go on (so that another line or a label near it is not counted).
     */
    public int paintedWidth(String a, String b, double fraction) {
        return edt(() -> {
            BufferedImage image = paintCanvas();
            Point2D from = map.screenOf(a);
            Point2D to = map.screenOf(b);
            double length = from.distance(to);
            double nx = -(to.getY() - from.getY()) / length;
            double ny = (to.getX() - from.getX()) / length;
            double x = from.getX() + (to.getX() - from.getX()) * fraction;
            double y = from.getY() + (to.getY() - from.getY()) * fraction;
            Color colour = MapColours.of(line(a, b), map.data().cutoff());
            int ground = 3 * 255;
            int threshold = (ground + colour.getRed() + colour.getGreen() + colour.getBlue()) / 2;
            int width = 0;
            for (int side : new int[] {1, -1}) {
                for (int step = side == 1 ? 0 : 1; step <= 20; step++) {
                    Color pixel = new Color(image.getRGB((int) Math.round(x + side * step * nx), (int) Math.round(y + side * step * ny)));
                    if (pixel.getRed() + pixel.getGreen() + pixel.getBlue() >= threshold) {
                        break;
                    }
                    width++;
                }
            }
            return width;
        });
    }

    /** The width of a line at this rate (bit/s), as the map's rule gives it. */
    public static float widthFor(long bitsPerSecond) {
        return MapLineWidth.forRate(bitsPerSecond);
    }

    /** The width of a line with links not shaped. */
    public static float unshapedWidth() {
        return MapLineWidth.UNSHAPED;
    }

    /** The pair a right click this fraction of the way along its line would open the force menu on, "a - b"; null for none. */
    public String lineHit(String a, String b, double fraction) {
        return edt(() -> {
            Point2D from = map.screenOf(a);
            Point2D to = map.screenOf(b);
            MapData.Line hit = map.lineAt(from.getX() + (to.getX() - from.getX()) * fraction,
                    from.getY() + (to.getY() - from.getY()) * fraction);
            return hit == null ? null : hit.first() + " - " + hit.second();
        });
    }

    /** Right-clicks this fraction of the way along the pair's line and chooses the menu item that starts with {@code item}. */
    public void chooseOnLine(String a, String b, double fraction, String item) {
        edt(() -> {
            Point2D from = map.screenOf(a);
            Point2D to = map.screenOf(b);
            javax.swing.JPopupMenu menu = map.menuAt(from.getX() + (to.getX() - from.getX()) * fraction,
                    from.getY() + (to.getY() - from.getY()) * fraction);
            for (java.awt.Component child : menu.getComponents()) {
                if (child instanceof javax.swing.JMenuItem menuItem && menuItem.getText().startsWith(item)) {
                    menuItem.doClick();
                    return null;
                }
            }
            throw new AssertionError("no item " + item + " in the menu of " + a + " - " + b);
        });
    }

    /** Whether the pair's line is drawn dashed (forced) in this state. */
    public boolean line(String a, String b, org.usarsim.wss.hub.core.PairState state) {
        return edt(() -> line(a, b).state() == state);
    }

    /** Brings the tab of this title to the front ("Routes", say). */
    public void showTab(String title) {
        Gui.run(() -> {
            JTabbedPane tabs = Gui.find(frame.getContentPane(), JTabbedPane.class, "tabs");
            tabs.setSelectedIndex(tabs.indexOfTab(title));
        });
    }

    /** Types the text into the filter field of the table of that name ("routes", say). */
    public void filter(String table, String text) {
        Gui.run(() -> Gui.find(frame.getContentPane(), javax.swing.JTextField.class, table + "Filter").setText(text));
    }

    /** Picks the two robots whose route the map draws, as a click on each does. */
    public void pick(String from, String to) {
        Gui.run(() -> map.pick(RoutePick.NONE.click(from).click(to)));
    }

    /** The line above the map: how to pick, or the route picked. */
    public String status() {
        return edt(map::status);
    }

    /** Selects the robot whose range the map draws. */
    public void select(String robot) {
        Gui.run(() -> map.select(robot));
    }

    /** On the event thread, from the test's thread or from a condition that already runs there. */
    /** The names' and the labels' boxes the map drew, and how many labels it left out; canvas pixels. */
    public record Labels(List<java.awt.geom.Rectangle2D> names, List<java.awt.geom.Rectangle2D> labels, int leftOut,
            java.awt.Dimension canvas) {
    }

    /** Paints the map now, as the window does, and reads where that painting put its names and labels. */
    public Labels paintedLabels() {
        return edt(() -> {
            javax.swing.JComponent canvas = map.canvas();
            BufferedImage image = new BufferedImage(canvas.getWidth(), canvas.getHeight(), BufferedImage.TYPE_INT_RGB);
            Graphics2D g = image.createGraphics();
            canvas.paint(g);
            g.dispose();
            LabelPlacer placed = map.placedLabels();
            return new Labels(placed.names(), placed.placed(), placed.leftOut(), canvas.getSize());
        });
    }

    private static <T> T edt(java.util.concurrent.Callable<T> action) {
        if (!javax.swing.SwingUtilities.isEventDispatchThread()) {
            return Gui.onEdt(action);
        }
        try {
            return action.call();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    /** The grey of a broken pair, the green of a strong one. */
    public static Color broken() {
        return MapColours.BROKEN;
    }

    public static Color strong() {
        return MapColours.STRONG;
    }

    private MapData.Line line(String a, String b) {
        return map.data().lines().stream()
                .filter(line -> line.first().equals(a) && line.second().equals(b) || line.first().equals(b) && line.second().equals(a))
                .findFirst().orElseThrow(() -> new AssertionError("no line " + a + " - " + b + " in " + map.data().lines()));
    }

    /** Event thread. */
    private BufferedImage paintCanvas() {
        BufferedImage image = new BufferedImage(map.canvas().getWidth(), map.canvas().getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        map.canvas().paint(g);
        g.dispose();
        return image;
    }
}
