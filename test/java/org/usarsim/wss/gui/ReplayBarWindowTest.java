package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.cells;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;

import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.MouseEvent;
import java.net.ServerSocket;
import java.util.List;
import java.util.Optional;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JSlider;
import javax.swing.JTable;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.model.FakeReplay;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.StubModel;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/**
 * The time bar (docs/gui.md), for real: a window under a display starts a server whose model
 * replays (a fake replay recording the calls); the bar shows, its button, speed box and slider
 * call the replay, its label shows the time; a jump that breaks a pair is followed by the tables,
 * the statistics and the map; at Stop the bar goes.
 */
@Timeout(60)
@Tag("slow")
class ReplayBarWindowTest {

    /**
     * A model that replays a 12-minute recording: r2 stands (the replay's time) metres east of r1,
     * and from 5 minutes on the pair is broken, as the recording had it; a jump applies that.
     */
    static final class ReplayingModel extends StubModel {
        final FakeReplay replay = new FakeReplay(720);

        ReplayingModel() {
            replay.onJump(seconds -> {
                if (seconds >= 300) {
                    links().breakConnectionsForPair("r1", "r2");
                } else {
                    links().resumeConnectionsForPair("r1", "r2");
                }
            });
        }

        @Override
        public String name() {
            return "ReplayingModel";
        }

        @Override
        public Optional<Replay> replay() {
            return Optional.of(replay);
        }

        @Override
        public Optional<Position> positionOf(String robot) {
            return Optional.of(robot.equals("r2") ? new Position(replay.timeSeconds(), 0, 0) : new Position(0, 0, 0));
        }

        @Override
        public boolean isActive() {
            return true;
        }

        @Override
        public double getSignalStrengthForPair(String from, String to) {
            return -50;
        }
    }

    private final ReplayingModel model = new ReplayingModel();
    private OpenWindow window;
    private HubServers servers;
    private WindowLog windowLog;
    private JFrame frame;

    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @BeforeEach
    void open() throws Exception {
        window = new OpenWindow(TestHub.config(true, 65536, 600, 1000, 30),
                List.of(ModelProvider.of(NoopPropagationModel::new), ModelProvider.of(() -> model)), "ReplayingModel");
        servers = window.servers;
        windowLog = window.windowLog;
        frame = window.frame;
    }

    @AfterEach
    void close() throws Exception {
        window.close();
    }

    /** The window's component of that type and name; from the test's thread or the event thread. */
    private <T extends java.awt.Component> T component(Class<T> type, String name) {
        if (javax.swing.SwingUtilities.isEventDispatchThread()) {
            return find(frame.getContentPane(), type, name);
        }
        return onEdt(() -> find(frame.getContentPane(), type, name));
    }

    /** Whether the time bar shows; from the test's thread (the event thread: {@link #barShowing}). */
    private boolean barShows() {
        return onEdt(this::barShowing);
    }

    private boolean barShowing() {
        return find(frame.getContentPane(), ReplayBar.class, "replayBar").isShowing();
    }

    private void press(String button, String expectedText) {
        JButton start = component(JButton.class, button);
        run(start::doClick);
        until(button + " says " + expectedText, () -> start.getText().equals(expectedText));
    }

    @Test
    void theBarShowsWhileTheModelReplaysItsControlsMoveTheReplayAndTheWindowFollowsAJump() throws Exception {
        assertFalse(barShows(), "no bar before Start");
        press("start", "Stop");
        until("the bar shows", this::barShowing);
        JLabel time = component(JLabel.class, "replayTime");
        JButton play = component(JButton.class, "replayPlay");
        @SuppressWarnings("unchecked")
        JComboBox<String> speed = component(JComboBox.class, "replaySpeed");
        JSlider slider = component(JSlider.class, "replaySlider");
        assertEquals("00:00 / 12:00", onEdt(time::getText));
        assertEquals(List.of("0.25x", "0.5x", "1x", "2x", "4x", "8x"),
                onEdt(() -> java.util.stream.IntStream.range(0, speed.getItemCount()).mapToObj(speed::getItemAt).toList()));
        assertEquals("1x", onEdt(speed::getSelectedItem));
        assertEquals(720_000, onEdt(slider::getMaximum));

        // The bar follows the replay's time (the window's 250 ms refresh).
        model.replay.time(65.5);
        until("the label follows the replay", () -> time.getText().equals("01:05 / 12:00"));
        until("the slider follows the replay", () -> slider.getValue() == 65_500);

        // Pause, then Play.
        assertEquals("Pause", onEdt(play::getText));
        run(play::doClick);
        assertEquals(List.of("pause"), model.replay.calls());
        until("the button offers Play", () -> play.getText().equals("Play"));
        run(play::doClick);
        assertEquals(List.of("pause", "play"), model.replay.calls());
        until("the button offers Pause", () -> play.getText().equals("Pause"));

        // 4x.
        run(() -> speed.setSelectedItem("4x"));
        assertEquals(List.of("pause", "play", "speed 4.0"), model.replay.calls());
        run(() -> speed.setSelectedItem("0.25x"));
        assertEquals("speed 0.25", model.replay.calls().get(3));

        // Two robots with a link, for the jump to break.
        int port = servers.running().port();
        try (TestRobot r1 = new TestRobot(port, "127.0.0.2"); TestRobot r2 = new TestRobot(port, "127.0.0.3")) {
            r1.initAccepting("r1");
            ServerSocket r2Accepts = r2.initAccepting("r2");
            int toR2 = r1.dns("r2", 0);
            JTable ports = component(JTable.class, "ports");
            until("r1 -> r2 listens", () -> cells(ports).size() == 1 && cells(ports).get(0).get(4).equals("yes"));
            JTable stats = component(JTable.class, "stats");
            until("the statistics show the pair up", () -> cells(stats).size() == 1 && cells(stats).get(0).contains("up"));

            // Dragging: the label follows the knob, nothing jumps until the release.
            run(() -> {
                slider.setValueIsAdjusting(true);
                slider.setValue(400_000);
            });
            assertEquals("06:40 / 12:00", onEdt(time::getText), "the label follows the knob while dragging");
            assertEquals(4, model.replay.calls().size(), "no jump while dragging");
            Thread.sleep(2 * MainWindow.REFRESH_MS); // refreshes while dragging leave the knob where it is
            assertEquals(400_000, (int) onEdt(slider::getValue));
            run(() -> slider.setValueIsAdjusting(false));
            assertEquals("jump 400.0", model.replay.calls().get(4), "the release jumps");
            until("the label shows the jump", () -> time.getText().equals("06:40 / 12:00"));

            // The jump broke the pair: the ports, the statistics and the map follow.
            until("the port stops listening", () -> cells(ports).get(0).get(4).equals("no"));
            until("the statistics show the pair broken", () -> cells(stats).get(0).contains("broken"));
            MapPanel map = onEdt(() -> Gui.all(frame.getContentPane(), MapPanel.class).get(0));
            until("the map shows r2 where the replay has it", () -> map.data().robots().stream()
                    .anyMatch(robot -> robot.name().equals("r2") && robot.position() != null && robot.position().x() == 400));
            assertTrue(toR2 > 0);
            r2Accepts.close();
        }

        press("start", "Start");
        assertFalse(barShows(), "the bar goes at Stop");
    }

    /** Issue 26, item 3: a click on the track jumps to where it was clicked, at once; an arrow key moves by a second. */
    @Test
    void aClickOnTheTrackJumpsWhereItWasClickedAndAnArrowKeyBySecond() throws Exception {
        press("start", "Stop");
        until("the bar shows", this::barShowing);
        JSlider slider = component(JSlider.class, "replaySlider");
        JLabel time = component(JLabel.class, "replayTime");
        until("the slider laid out", () -> slider.getWidth() > 100);
        int x = onEdt(() -> slider.getWidth() * 3 / 4);
        int y = onEdt(() -> slider.getHeight() / 2);
        int clicked = onEdt(() -> ((javax.swing.plaf.basic.BasicSliderUI) slider.getUI()).valueForXPosition(x));
        assertTrue(clicked > 400_000 && clicked < 650_000, "three quarters of 12 minutes: " + clicked);
        run(() -> {
            long when = System.currentTimeMillis();
            slider.dispatchEvent(new MouseEvent(slider, MouseEvent.MOUSE_PRESSED, when, InputEvent.BUTTON1_DOWN_MASK, x, y, 1, false,
                    MouseEvent.BUTTON1));
            slider.dispatchEvent(new MouseEvent(slider, MouseEvent.MOUSE_RELEASED, when, 0, x, y, 1, false, MouseEvent.BUTTON1));
        });
        assertEquals(List.of("jump " + clicked / 1000.0), model.replay.calls(), "one jump, to where it was clicked");
        until("the label shows it", () -> time.getText().equals(ReplayBar.text(clicked / 1000.0, 720)));

        run(() -> slider.dispatchEvent(new KeyEvent(slider, KeyEvent.KEY_PRESSED, System.currentTimeMillis(), 0, KeyEvent.VK_RIGHT,
                KeyEvent.CHAR_UNDEFINED)));
        assertEquals("jump " + (clicked + 1000) / 1000.0, model.replay.calls().get(1), "the right arrow: a second on");
        until("the label moved by a second", () -> time.getText().equals(ReplayBar.text((clicked + 1000) / 1000.0, 720)));
        run(() -> slider.dispatchEvent(new KeyEvent(slider, KeyEvent.KEY_PRESSED, System.currentTimeMillis(), 0, KeyEvent.VK_LEFT,
                KeyEvent.CHAR_UNDEFINED)));
        run(() -> slider.dispatchEvent(new KeyEvent(slider, KeyEvent.KEY_PRESSED, System.currentTimeMillis(), 0, KeyEvent.VK_LEFT,
                KeyEvent.CHAR_UNDEFINED)));
        assertEquals("jump " + (clicked - 1000) / 1000.0, model.replay.calls().get(3), "the left arrow: a second back");
    }

    @Test
    void aModelThatReplaysNothingHasNoBar() throws Exception {
        run(() -> component(JComboBox.class, "model").setSelectedItem("NoopPropagationModel"));
        press("start", "Stop");
        Thread.sleep(2 * MainWindow.REFRESH_MS);
        assertFalse(barShows());
        press("start", "Start");
    }

    @Test
    void textsOfTheBar() {
        assertEquals("00:00 / 00:00", ReplayBar.text(0, 0));
        assertEquals("01:05 / 12:00", ReplayBar.text(65.99, 720));
        assertEquals("125:00 / 180:00", ReplayBar.text(7500, 10800));
        assertEquals("0.25x", ReplayBar.speedText(0.25));
        assertEquals("1x", ReplayBar.speedText(1));
        assertEquals("8x", ReplayBar.speedText(8.0));
    }
}
