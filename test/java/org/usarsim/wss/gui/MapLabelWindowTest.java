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
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.WssEventListener;

/**
 * Issue 36, item 5 (the last part), read off the real window's map under a display: a broken
 * pair's label says "broken" after its strength (docs/gui.md: a pair that is not up says its
 * state), as the map painted it.
 */
@Tag("slow")
@Timeout(60)
class MapLabelWindowTest {

    /** How far east of Base each robot is, in metres (Scout 60, Relay halfway). */
    private static final java.util.Map<String, Integer> EAST = java.util.Map.of("Base", 0, "Relay", 30, "Scout", 60);

    /** Scout 60 m east of Base, Relay halfway, every pair beyond the cutoff: broken. */
    static final class OutOfRangeModel implements PropagationModel {
        private volatile boolean active;

        @Override
        public String name() {
            return "OutOfRangeModel";
        }

        @Override
        public void setRobotLinkModel(RobotLinkModel linkModel) {
        }

        @Override
        public void setEventListener(WssEventListener listener) {
        }

        @Override
        public void start() {
            active = true;
        }

        @Override
        public void shutdown() {
            active = false;
        }

        @Override
        public boolean isActive() {
            return active;
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
            return Optional.of(new Position(EAST.getOrDefault(robot, 60), 0, 0));
        }

        @Override
        public double cutoff() {
            return -93;
        }
    }

    private OpenWindow window;

    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @AfterEach
    void close() throws Exception {
        if (window != null) {
            window.close();
        }
    }

    @Test
    void noLabelLiesOverARobotsDot() throws Exception {
        JFrame frame = openAndStart();
        int port = window.servers.running().port();
        try (TestRobot base = new TestRobot(port, "127.0.0.2"); TestRobot relay = new TestRobot(port, "127.0.0.3");
                TestRobot scout = new TestRobot(port, "127.0.0.4")) {
            base.initAccepting("Base");
            relay.initAccepting("Relay");
            scout.initAccepting("Scout");
            MapPanel map = showMap(frame);
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
    }

    private JFrame openAndStart() throws Exception {
        window = new OpenWindow(TestHub.config(true, 65536, 600, 1000, 30), List.of(ModelProvider.of(OutOfRangeModel::new)),
                "OutOfRangeModel");
        JFrame frame = window.frame;
        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        run(start::doClick);
        until("the server runs", () -> start.getText().equals("Stop"));
        return frame;
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
        window = new OpenWindow(TestHub.config(true, 65536, 600, 1000, 30), List.of(ModelProvider.of(OutOfRangeModel::new)),
                "OutOfRangeModel");
        JFrame frame = window.frame;
        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        run(start::doClick);
        until("the server runs", () -> start.getText().equals("Stop"));
        int port = window.servers.running().port();
        try (TestRobot base = new TestRobot(port, "127.0.0.2"); TestRobot scout = new TestRobot(port, "127.0.0.3")) {
            base.initAccepting("Base");
            scout.initAccepting("Scout");
            MapPanel map = onEdt(() -> all(frame.getContentPane(), MapPanel.class).get(0));
            run(() -> {
                JTabbedPane tabs = find(frame.getContentPane(), JTabbedPane.class, "tabs");
                tabs.setSelectedIndex(tabs.indexOfTab("Map"));
            });
            until("the map draws the pair's label, saying its state: " + onEdt(() -> map.placedLabels().texts()), () -> {
                map.canvas().repaint(); // painted anew at the next turn of the event thread
                return map.placedLabels().texts().contains("-94.1 dBm, broken");
            });
        }
    }
}
