package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.all;
import static org.usarsim.wss.gui.Gui.cells;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;

import java.awt.Color;
import java.awt.event.KeyEvent;
import java.awt.event.MouseEvent;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JTabbedPane;
import javax.swing.JTable;
import javax.swing.JTextField;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.StubModel;

/**
 * Issue 34, item 3, on the real window under a display: robots in a chain, 10 m apart with a range
 * of 12 m (Alpha, R1, R2, R3, Scout) and Lost 30 m off it, Alpha the base. A click on Alpha's dot and
 * one on Scout's picks the route, which the map draws over four hops with their strengths and the
 * status line says; a double click keeps the pick; a third click clears, and so does Escape; a click
 * still selects the robot.
 * Lost is drawn cut off. The Routes tab lists every ordered pair and filters them.
 */
@Tag("slow")
@Timeout(60)
class RouteWindowTest {

    /** Each robot's place, x and y in metres: the chain zigzags, so that each hop's label has room beside it. */
    private static final Map<String, List<Integer>> AT = Map.of("Alpha", List.of(0, 0), "R1", List.of(8, 6), "R2", List.of(16, 0),
            "R3", List.of(24, 6), "Scout", List.of(32, 0), "Lost", List.of(16, 30));

    /** Each robot at {@link #AT}; a pair talks within 12 m, its strength -50 dBm less a dB a metre. */
    static final class ChainModel extends StubModel {
        @Override
        public String name() {
            return "ChainModel";
        }

        @Override
        public double getSignalStrengthForPair(String from, String to) {
            return -50 - distance(from, to);
        }

        @Override
        public boolean connectionIsPossibleForPair(String from, String to) {
            return inRange(from, to);
        }

        static boolean inRange(String from, String to) {
            return distance(from, to) <= 12;
        }

        private static double distance(String from, String to) {
            return Math.hypot(AT.get(from).get(0) - AT.get(to).get(0), AT.get(from).get(1) - AT.get(to).get(1));
        }

        /** Breaks every pair of these robots out of range, as a model's poll would. */
        void breakOutOfRange(List<String> names) {
            for (String a : names) {
                for (String b : names) {
                    if (a.compareTo(b) < 0 && !inRange(a, b)) {
                        links().breakConnectionsForPair(a, b);
                    }
                }
            }
        }

        @Override
        public Optional<Position> positionOf(String robot) {
            return Optional.of(new Position(AT.get(robot).get(0), AT.get(robot).get(1), 0));
        }

        @Override
        public double cutoff() {
            return -62;
        }
    }

    private OpenWindow window;

    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @Test
    void twoClicksPickTheRouteTheMapDrawsAndTheRoutesTabListsEveryPair() throws Exception {
        List<TestRobot> robots = new ArrayList<>();
        try (OpenWindow opened = new OpenWindow(TestHub.config(true, 65536, 600, 1000, 30), List.of(ModelProvider.of(ChainModel::new)),
                "ChainModel")) {
            window = opened;
            pickAndList(robots);
        } finally {
            for (TestRobot robot : robots) {
                robot.close();
            }
        }
    }

    private void pickAndList(List<TestRobot> robots) throws Exception {
        JButton start = onEdt(() -> find(window.frame.getContentPane(), JButton.class, "start"));
        run(start::doClick);
        until("the server runs", () -> start.getText().equals("Stop"));
        int port = window.servers.running().port();
        List<String> names = List.of("Alpha", "R1", "R2", "R3", "Scout", "Lost");
        for (String name : names) {
            TestRobot robot = new TestRobot(port, "127.0.0." + (2 + robots.size()));
            robots.add(robot);
            robot.initAccepting(name);
        }
        for (int i = 0; i < names.size(); i++) { // a DNS makes the pair known to the hub, whose routes go over pairs up
            for (int j = i + 1; j < names.size(); j++) {
                robots.get(i).dns(names.get(j), 0);
            }
        }
        ((ChainModel) window.servers.running().model()).breakOutOfRange(names);
        window.servers.hubs().get(0).setRouteBase("Alpha");
        MapPanel map = showTab("Map", MapPanel.class);
        until("the map has the route Alpha - Scout and Lost cut off", () -> map.data().routes().route("Alpha", "Scout").hops() == 4
                && map.data().routes().isCutOff("Lost") && map.screenOf("Scout") != null);

        assertEquals(RouteText.HOW, onEdt(map::status));
        click(map, "Alpha");
        assertEquals("Route from Alpha: click another robot (a click on Alpha or Escape clears)", onEdt(map::status));
        click(map, "Scout");
        assertEquals(new RoutePick("Alpha", "Scout"), onEdt(map::pick));
        assertEquals("Scout", onEdt(map::selected), "a click still selects the robot whose range is drawn");
        DrawnRoute drawn = onEdt(map::route);
        assertEquals(List.of("Alpha", "R1", "R2", "R3", "Scout"), drawn.route().path());
        assertEquals("Alpha -> Scout: 4 hops via R1, R2, R3; weakest hop Alpha -> R1 at -60.0 dBm", onEdt(map::status));
        List<String> texts = onEdt(() -> {
            paint(map);
            return map.placedLabels().texts();
        });
        assertEquals(4, texts.stream().filter("-60.0 dBm"::equals).count(), "each hop labelled with its strength: " + texts);
        assertTrue(onEdt(() -> near(paint(map), map.screenOf("Lost"), MapSymbols.CUT_OFF)), "Lost drawn cut off");
        assertTrue(onEdt(() -> near(paint(map), map.screenOf("Alpha"), MapSymbols.BASE)), "Alpha drawn as the base");

        click(map, "R1", 2); // a double click fits the map, and picks nothing
        assertEquals(new RoutePick("Alpha", "Scout"), onEdt(map::pick), "a double click keeps the pick");
        click(map, "R1");
        assertEquals(RoutePick.NONE, onEdt(map::pick), "a third click clears");
        assertNull(onEdt(map::route));
        assertEquals(RouteText.HOW, onEdt(map::status));
        click(map, "Alpha");
        run(() -> map.canvas().dispatchEvent(new KeyEvent(map.canvas(), KeyEvent.KEY_PRESSED, System.currentTimeMillis(), 0,
                KeyEvent.VK_ESCAPE, KeyEvent.CHAR_UNDEFINED)));
        assertEquals(RoutePick.NONE, onEdt(map::pick), "Escape clears");

        RoutesPanel panel = showTab("Routes", RoutesPanel.class);
        JTable table = onEdt(() -> find(panel, JTable.class, "routes"));
        until("the Routes tab lists every ordered pair", () -> table.getRowCount() == 30);
        JTextField filter = onEdt(() -> find(panel, JTextField.class, "routesFilter"));
        run(() -> filter.setText("alpha scout"));
        assertEquals(List.of(List.of("Alpha", "Scout", "4", "Alpha > R1 > R2 > R3 > Scout", "Alpha > R1, -60.0 dBm", "-")),
                onEdt(() -> cells(table)));
        run(() -> filter.setText("lost alpha"));
        assertEquals(List.of(List.of("Lost", "Alpha", "", "no route", "", "-")), onEdt(() -> cells(table)));
    }

    private <T extends java.awt.Component> T showTab(String title, Class<T> type) {
        run(() -> {
            JTabbedPane tabs = find(window.frame.getContentPane(), JTabbedPane.class, "tabs");
            tabs.setSelectedIndex(tabs.indexOfTab(title));
        });
        return onEdt(() -> all(window.frame.getContentPane(), type).get(0));
    }

    /** A left click on the robot's dot, as the mouse gives it. */
    private static void click(MapPanel map, String robot) {
        click(map, robot, 1);
    }

    /** As many left clicks on the robot's dot as {@code clicks}, one after the other: a double click for 2. */
    private static void click(MapPanel map, String robot, int clicks) {
        run(() -> {
            Point2D at = map.screenOf(robot);
            JComponent canvas = map.canvas();
            long now = System.currentTimeMillis();
            for (int count = 1; count <= clicks; count++) {
                canvas.dispatchEvent(new MouseEvent(canvas, MouseEvent.MOUSE_PRESSED, now, MouseEvent.BUTTON1_DOWN_MASK,
                        (int) Math.round(at.getX()), (int) Math.round(at.getY()), count, false, MouseEvent.BUTTON1));
                canvas.dispatchEvent(new MouseEvent(canvas, MouseEvent.MOUSE_RELEASED, now, 0,
                        (int) Math.round(at.getX()), (int) Math.round(at.getY()), count, false, MouseEvent.BUTTON1));
            }
        });
    }

    /** Paints the map as the window does (event thread). */
    private static BufferedImage paint(MapPanel map) {
        JComponent canvas = map.canvas();
        BufferedImage image = new BufferedImage(canvas.getWidth(), canvas.getHeight(), BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = image.createGraphics();
        canvas.paint(g);
        g.dispose();
        return image;
    }

    /** Whether some pixel within 10 of the point has this colour (give or take antialiasing). */
    private static boolean near(BufferedImage image, Point2D at, Color colour) {
        for (int dx = -10; dx <= 10; dx++) {
            for (int dy = -10; dy <= 10; dy++) {
                Color pixel = new Color(image.getRGB((int) at.getX() + dx, (int) at.getY() + dy));
                if (Math.abs(pixel.getRed() - colour.getRed()) + Math.abs(pixel.getGreen() - colour.getGreen())
                        + Math.abs(pixel.getBlue() - colour.getBlue()) < 24) {
                    return true;
                }
            }
        }
        return false;
    }
}
