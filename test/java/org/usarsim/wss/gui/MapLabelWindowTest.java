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

    /** Scout 60 m east of Base, beyond the cutoff: the pair is broken. */
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
            return Optional.of(new Position(robot.equals("Base") ? 0 : 60, 0, 0));
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
