package org.usarsim.wss.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.geom.Line2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.List;
import java.util.Objects;
import javax.swing.DefaultListModel;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JPopupMenu;
import javax.swing.JScrollPane;
import javax.swing.SwingUtilities;
import org.usarsim.wss.model.Wall;

/**
 * The "Map" tab: the robots at their positions (names beside the dots), a line per pair coloured
 * by {@link MapColours}, as wide as {@link MapLineWidth} says (its rate, with links shaped), dashed
 * when forced, the selected robot's range as a circle, the walls, and
 * beside it the robots without a position. Fits the world until the user zooms (wheel) or pans
 * (drag); a double click fits it again. A click on a dot selects the robot and picks it as one end
 * of a route ({@link RoutePick}: the status line above the map says how, and the route picked); a
 * right click on a line opens the {@link ForceMenu}. Event thread only; painting ({@link MapPainter})
 * reads the {@link MapData} it was given.
 */
final class MapPanel extends JPanel {

    static final int MARGIN = 40;
    /** How near, in pixels, a click must be to a dot or a line to hit it. */
    static final int HIT = 8;
    /** A robot's dot, in pixels. */
    static final int DOT = 10;

    private final Canvas canvas = new Canvas();
    private final DefaultListModel<String> unplaced = new DefaultListModel<>();
    private final ForceMenu forceMenu;
    private MapData data = MapData.EMPTY;
    /** The user's zoom and pan; null while the map fits the world by itself. */
    private MapTransform userTransform;
    private String selected;
    /** The two robots picked for a route, and the line above the map that says it. */
    private RoutePick pick = RoutePick.NONE;
    private final JLabel status = new JLabel(RouteText.HOW);
    /** The labels' places of the last painting (tests read what the map drew). */
    private LabelPlacer lastLabels = new LabelPlacer(new Rectangle2D.Double());

    MapPanel(ForceMenu forceMenu) {
        super(new BorderLayout(8, 0));
        this.forceMenu = forceMenu;
        canvas.setName("map");
        JList<String> list = new JList<>(unplaced);
        list.setName("withoutPosition");
        JPanel side = new JPanel(new BorderLayout(0, 4));
        side.add(new JLabel("Without a position"), BorderLayout.NORTH);
        JScrollPane scroll = new JScrollPane(list);
        scroll.setPreferredSize(new Dimension(160, 100));
        side.add(scroll, BorderLayout.CENTER);
        status.setName("mapStatus");
        add(status, BorderLayout.NORTH);
        add(canvas, BorderLayout.CENTER);
        add(side, BorderLayout.EAST);
        getInputMap(WHEN_ANCESTOR_OF_FOCUSED_COMPONENT).put(javax.swing.KeyStroke.getKeyStroke("ESCAPE"), "clearRoute");
        getActionMap().put("clearRoute", new javax.swing.AbstractAction() {
            @Override
            public void actionPerformed(java.awt.event.ActionEvent e) {
                pick(RoutePick.NONE);
            }
        });
    }

    /** Shows what the last poll gathered. */
    void show(MapData newData) {
        data = Objects.requireNonNull(newData);
        List<String> without = data.robots().stream().filter(robot -> robot.position() == null).map(MapData.Robot::name).toList();
        if (!without.equals(java.util.Collections.list(unplaced.elements()))) {
            unplaced.clear();
            unplaced.addAll(without);
        }
        showRoute();
        canvas.repaint();
    }

    /** The robots picked for a route. */
    RoutePick pick() {
        return pick;
    }

    /** Picks the route's robots (event thread): the map draws their route, the status line says it. */
    void pick(RoutePick newPick) {
        pick = Objects.requireNonNull(newPick);
        showRoute();
        canvas.repaint();
    }

    /** The route the map draws now, over the picture it shows; null while two robots are not picked. */
    DrawnRoute route() {
        return DrawnRoute.of(pick, data);
    }

    /** The status line above the map, as it reads now. */
    String status() {
        return status.getText();
    }

    private void showRoute() {
        DrawnRoute route = route();
        String text = RouteText.status(pick, route == null ? null : route.route(), route != null && route.shaped());
        if (!text.equals(status.getText())) {
            status.setText(text);
        }
    }

    /** What the map shows now. */
    MapData data() {
        return data;
    }

    /** Selects the robot whose range is drawn (null: none). */
    void select(String robot) {
        selected = robot;
        canvas.repaint();
    }

    String selected() {
        return selected;
    }

    /** Where the last painting put the names and the labels, and how many labels it left out. */
    LabelPlacer placedLabels() {
        return lastLabels;
    }

    /** The transform the map is drawn with now: the user's, or the one that fits the world into the canvas. */
    MapTransform transform() {
        return userTransform != null ? userTransform : MapTransform.fit(worldBounds(), canvas.getWidth(), canvas.getHeight(), MARGIN);
    }

    /** The canvas the map is painted on (tests and screenshots read it). */
    JComponent canvas() {
        return canvas;
    }

    /** Where the robot's dot is on the canvas; null when it has no position or is not shown. */
    Point2D screenOf(String robot) {
        return MapPainter.screenOf(transform(), data, robot);
    }

    /** The rectangle of the world that fitting shows: the positions and the walls. */
    private Rectangle2D worldBounds() {
        Rectangle2D bounds = null;
        for (MapData.Robot robot : data.robots()) {
            if (robot.position() != null) {
                bounds = add(bounds, robot.position().x(), robot.position().y());
            }
        }
        for (Wall wall : data.walls()) {
            bounds = add(bounds, wall.x1(), wall.y1());
            bounds = add(bounds, wall.x2(), wall.y2());
        }
        return bounds != null ? bounds : new Rectangle2D.Double(0, 0, 0, 0);
    }

    private static Rectangle2D add(Rectangle2D bounds, double x, double y) {
        if (bounds == null) {
            return new Rectangle2D.Double(x, y, 0, 0);
        }
        bounds.add(x, y);
        return bounds;
    }

    /** The robot whose dot is within {@link #HIT} pixels of the point, the nearest; null when none. */
    String robotAt(double x, double y) {
        String found = null;
        double best = HIT;
        for (MapData.Robot robot : data.robots()) {
            Point2D at = screenOf(robot.name());
            if (at != null && at.distance(x, y) <= best) {
                best = at.distance(x, y);
                found = robot.name();
            }
        }
        return found;
    }

    /** The line within {@link #HIT} pixels of the point, the nearest; null when none. */
    MapData.Line lineAt(double x, double y) {
        MapData.Line found = null;
        double best = HIT;
        for (MapData.Line line : data.lines()) {
            Point2D a = screenOf(line.first());
            Point2D b = screenOf(line.second());
            if (a != null && b != null) {
                double distance = Line2D.ptSegDist(a.getX(), a.getY(), b.getX(), b.getY(), x, y);
                if (distance <= best) {
                    best = distance;
                    found = line;
                }
            }
        }
        return found;
    }

    /** The force menu of the line a right click at this point hits; null when it hits none. */
    JPopupMenu menuAt(double x, double y) {
        MapData.Line line = lineAt(x, y);
        return line == null ? null : forceMenu.menuFor(line.first(), line.second());
    }

    /** The map itself. */
    private final class Canvas extends JComponent {

        private Point2D dragFrom;
        /** The pick before the last single click: a double click's first click is taken back. */
        private RoutePick beforeClick = RoutePick.NONE;

        Canvas() {
            setOpaque(true);
            setBackground(Color.WHITE);
            setPreferredSize(new Dimension(600, 400));
            setFocusable(true);
            MouseAdapter mouse = new MouseAdapter() {
                @Override
                public void mousePressed(MouseEvent e) {
                    if (e.isPopupTrigger()) {
                        popup(e);
                    } else if (SwingUtilities.isLeftMouseButton(e)) {
                        dragFrom = e.getPoint();
                        if (e.getClickCount() == 2) {
                            userTransform = null;
                            pick(beforeClick); // a double click fits; its first click picks nothing
                        } else {
                            String robot = robotAt(e.getX(), e.getY());
                            beforeClick = pick;
                            if (robot != null) {
                                select(robot);
                                pick(pick.click(robot));
                            }
                            requestFocusInWindow(); // Escape clears the pick
                        }
                    }
                }

                @Override
                public void mouseReleased(MouseEvent e) {
                    dragFrom = null;
                    if (e.isPopupTrigger()) {
                        popup(e);
                    }
                }

                @Override
                public void mouseDragged(MouseEvent e) {
                    if (dragFrom != null) {
                        userTransform = transform().pan(e.getX() - dragFrom.getX(), e.getY() - dragFrom.getY());
                        dragFrom = e.getPoint();
                        repaint();
                    }
                }

                @Override
                public void mouseWheelMoved(MouseWheelEvent e) {
                    userTransform = transform().zoom(Math.pow(1.15, -e.getPreciseWheelRotation()), e.getX(), e.getY());
                    repaint();
                }
            };
            addMouseListener(mouse);
            addMouseMotionListener(mouse);
            addMouseWheelListener(mouse);
        }

        private void popup(MouseEvent e) {
            JPopupMenu menu = menuAt(e.getX(), e.getY());
            if (menu != null) {
                menu.show(this, e.getX(), e.getY());
            }
        }

        @Override
        protected void paintComponent(Graphics graphics) {
            Graphics2D g = (Graphics2D) graphics.create();
            try {
                lastLabels = new MapPainter(getWidth(), getHeight(), getFont(), getBackground(), selected, route()).paint(g, transform(), data);
            } finally {
                g.dispose();
            }
        }
    }
}
