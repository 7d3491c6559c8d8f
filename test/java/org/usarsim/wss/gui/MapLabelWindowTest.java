package org.usarsim.wss.gui;

import static org.usarsim.wss.gui.Gui.all;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;

import java.util.List;
import java.util.Optional;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JTabbedPane;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.StubModel;

/**
 * Issue 36, item 5, read off the real window's map under a display, as the map painted it: a
 * broken pair's label says "broken" after its strength (docs/gui.md: a pair that is not up says
 * its state); no label lies over a robot's dot; a label keeps off the other pairs' lines; a wall
 * through a robot's name does not strike it through.
 */
@Tag("slow")
@Timeout(60)
class MapLabelWindowTest {

    /** Every pair beyond the cutoff, broken; by default Scout 60 m east of Base, Relay halfway. */
    static final class OutOfRangeModel extends StubModel {
        /** Each robot's place, x and y in metres. */
        private final java.util.Map<String, List<Integer>> at;
        private final List<org.usarsim.wss.model.Wall> walls;

        OutOfRangeModel() {
            this(java.util.Map.of("Base", List.of(0, 0), "Relay", List.of(30, 0), "Scout", List.of(60, 0)));
        }

        OutOfRangeModel(java.util.Map<String, List<Integer>> at) {
            this(at, List.of());
        }

        OutOfRangeModel(java.util.Map<String, List<Integer>> at, List<org.usarsim.wss.model.Wall> walls) {
            this.at = at;
            this.walls = walls;
        }

        @Override
        public String name() {
            return "OutOfRangeModel";
        }

        @Override
        public double getSignalStrengthForPair(String from, String to) {
            return -94.1;
        }

        @Override
        public boolean connectionIsPossibleForPair(String from, String to) {
            return false;
        }

        @Override
        public Optional<Position> positionOf(String robot) {
            List<Integer> xy = at.getOrDefault(robot, List.of(60, 0));
            return Optional.of(new Position(xy.get(0), xy.get(1), 0));
        }

        @Override
        public List<org.usarsim.wss.model.Wall> walls() {
            return walls;
        }

        @Override
        public double cutoff() {
            return -93;
        }
    }

    private OpenWindow window;
    private final List<TestRobot> robots = new java.util.ArrayList<>();

    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @AfterEach
    void close() throws Exception {
        for (TestRobot robot : robots) {
            robot.close();
        }
        if (window != null) {
            window.close();
        }
    }

    @Test
    void noLabelLiesOverARobotsDot() throws Exception {
        openAndStart(OutOfRangeModel::new);
        MapPanel map = mapOf("Base", "Relay", "Scout");
        // Base - Scout's label would go at the middle of its line, where Relay's dot is.
        until("the map draws the three pairs' labels", () -> {
            map.canvas().repaint();
            return map.placedLabels().texts().size() + map.placedLabels().leftOut() == 3;
        });
        List<String> over = onEdt(() -> {
            List<String> found = new java.util.ArrayList<>();
            for (String robot : List.of("Base", "Relay", "Scout")) {
                java.awt.geom.Rectangle2D dot = MapPainter.dotBox(map.screenOf(robot));
                map.placedLabels().placed().stream().filter(dot::intersects).forEach(box -> found.add(robot + "'s dot under " + box));
            }
            return found;
        });
        org.junit.jupiter.api.Assertions.assertEquals(List.of(), over);
    }

    @Test
    void theOuterPairOfThreeInALineIsDrawnAroundTheMiddleOne() throws Exception {
        openAndStart(OutOfRangeModel::new);
        MapPanel map = mapOf("Base", "Relay", "Scout");
        until("the map draws the three pairs' lines", () -> {
            map.canvas().repaint();
            return map.placedLabels().lines().size() == 3;
        });
        // Each line as drawn touches two dots, its ends': Base - Scout's does not run through Relay's, under the two shorter lines.
        List<String> through = onEdt(() -> {
            List<String> found = new java.util.ArrayList<>();
            for (java.awt.Shape line : map.placedLabels().lines()) {
                java.awt.Shape outline = new java.awt.BasicStroke(1).createStrokedShape(line);
                List<String> dots = List.of("Base", "Relay", "Scout").stream()
                        .filter(robot -> outline.intersects(MapPainter.dotBox(map.screenOf(robot)))).toList();
                if (dots.size() > 2) {
                    found.add(line + " through " + dots);
                }
            }
            return found;
        });
        org.junit.jupiter.api.Assertions.assertEquals(List.of(), through);
    }

    @Test
    void aLabelKeepsOffTheOtherPairsLines() throws Exception {
        // Alpha - Delta east-west, Bravo - Charlie north-south a little east of its middle: Alpha - Delta's label, beside
        // its middle, would be crossed by Bravo - Charlie's line.
        java.util.Map<String, List<Integer>> cross = java.util.Map.of("Alpha", List.of(0, 0), "Bravo", List.of(33, -30),
                "Charlie", List.of(33, 30), "Delta", List.of(60, 0));
        openAndStart(() -> new OutOfRangeModel(cross));
        MapPanel map = mapOf("Alpha", "Bravo", "Charlie", "Delta");
        until("the map draws the six pairs' labels", () -> {
            map.canvas().repaint();
            return map.placedLabels().texts().size() + map.placedLabels().leftOut() == 6;
        });
        List<String> crossed = onEdt(() -> {
            List<java.awt.geom.Line2D> lines = new java.util.ArrayList<>();
            List<String> names = List.of("Alpha", "Bravo", "Charlie", "Delta");
            for (int i = 0; i < names.size(); i++) {
                for (int j = i + 1; j < names.size(); j++) {
                    lines.add(new java.awt.geom.Line2D.Double(map.screenOf(names.get(i)), map.screenOf(names.get(j))));
                }
            }
            List<String> found = new java.util.ArrayList<>();
            for (java.awt.geom.Rectangle2D box : map.placedLabels().placed()) {
                // Its own line may touch it; no other may cross it.
                long crossing = lines.stream().filter(line -> line.intersects(box)).count();
                if (crossing > 1) {
                    found.add(box + " crossed by " + crossing + " lines");
                }
            }
            return found;
        });
        org.junit.jupiter.api.Assertions.assertEquals(List.of(), crossed);
    }

    @Test
    void aWallThroughARobotsNameDoesNotStrikeItThrough() throws Exception {
        // Base and Scout 60 m apart, a wall along y = 0.8 m: through Base's name, drawn right of its dot and above it.
        java.util.Map<String, List<Integer>> apart = java.util.Map.of("Base", List.of(0, 0), "Scout", List.of(60, 0));
        List<org.usarsim.wss.model.Wall> wall = List.of(new org.usarsim.wss.model.Wall(-10, 0.8, 70, 0.8));
        openAndStart(() -> new OutOfRangeModel(apart, wall));
        MapPanel map = mapOf("Base", "Scout");
        until("the map draws both names", () -> {
            map.canvas().repaint();
            return map.placedLabels().names().size() == 2 && map.data().walls().size() == 1;
        });
        String struck = onEdt(() -> {
            javax.swing.JComponent canvas = map.canvas();
            java.awt.image.BufferedImage image = new java.awt.image.BufferedImage(canvas.getWidth(), canvas.getHeight(),
                    java.awt.image.BufferedImage.TYPE_INT_RGB);
            java.awt.Graphics2D g = image.createGraphics();
            canvas.paint(g);
            g.dispose();
            java.awt.geom.Rectangle2D name = map.placedLabels().names().get(0);
            java.awt.geom.Point2D wallAt = map.transform().toScreen(0, 0.8);
            if (wallAt.getY() < name.getMinY() || wallAt.getY() > name.getMaxY()) {
                return "the wall (y " + wallAt.getY() + ") misses the name " + name;
            }
            int wallPixels = 0;
            for (int x = (int) name.getMinX(); x < name.getMaxX(); x++) {
                for (int y = (int) name.getMinY(); y < name.getMaxY(); y++) {
                    java.awt.Color pixel = new java.awt.Color(image.getRGB(x, y));
                    if (Math.abs(pixel.getRed() - MapPainter.WALL.getRed()) < 24 && Math.abs(pixel.getGreen() - MapPainter.WALL.getGreen()) < 24
                            && Math.abs(pixel.getBlue() - MapPainter.WALL.getBlue()) < 24) {
                        wallPixels++;
                    }
                }
            }
            return wallPixels == 0 ? "" : wallPixels + " pixels of the wall's colour in the name's box " + name;
        });
        org.junit.jupiter.api.Assertions.assertEquals("", struck);
    }

    /** Registers robots of these names, each from an address of its own, and shows the map. */
    private MapPanel mapOf(String... names) throws Exception {
        int port = window.servers.running().port();
        for (String name : names) {
            TestRobot robot = new TestRobot(port, "127.0.0." + (2 + robots.size()));
            robots.add(robot);
            robot.initAccepting(name);
        }
        return showMap(window.frame);
    }

    private void openAndStart(java.util.function.Supplier<PropagationModel> model) throws Exception {
        window = new OpenWindow(TestHub.config(true, 65536, 600, 1000, 30), List.of(ModelProvider.of(model)),
                "OutOfRangeModel");
        JFrame frame = window.frame;
        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        run(start::doClick);
        until("the server runs", () -> start.getText().equals("Stop"));
    }

    private static MapPanel showMap(JFrame frame) {
        run(() -> {
            JTabbedPane tabs = find(frame.getContentPane(), JTabbedPane.class, "tabs");
            tabs.setSelectedIndex(tabs.indexOfTab("Map"));
        });
        return onEdt(() -> all(frame.getContentPane(), MapPanel.class).get(0));
    }

    @Test
    void aBrokenPairsLabelSaysBroken() throws Exception {
        openAndStart(OutOfRangeModel::new);
        MapPanel map = mapOf("Base", "Scout");
        until("the map draws the pair's label, saying its state", () -> {
            map.canvas().repaint(); // painted anew at the next turn of the event thread
            return map.placedLabels().texts().contains("-94.1 dBm, broken");
        });
    }
}
