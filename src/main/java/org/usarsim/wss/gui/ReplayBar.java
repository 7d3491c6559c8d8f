package org.usarsim.wss.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.util.List;
import java.util.Locale;
import java.util.logging.Level;
import java.util.logging.Logger;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.ActionMap;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.SwingUtilities;
import javax.swing.plaf.basic.BasicSliderUI;
import java.awt.event.ActionEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseListener;
import org.usarsim.wss.Decimals;
import org.usarsim.wss.model.Replay;

/**
 * The time bar under the tabs while the server's model replays a recording (docs/gui.md, "The
 * time bar"): Pause / Play, the speed (0.25x to 8x), the time {@code mm:ss / mm:ss} and a slider
 * over the recording to jump (on release; the time follows the knob while it is dragged). It
 * follows the replay at every refresh of the window ({@link #follow}); hidden while no replay
 * runs. Named replayPlay, replaySpeed, replayTime, replaySlider. Event thread only: the
 * {@link Replay}'s methods return at once.
 */
final class ReplayBar extends JPanel {

    private static final Logger LOG = Logger.getLogger(ReplayBar.class.getName());
    /** The speeds offered, as the combo box shows them; each is the number before the x. */
    static final List<String> SPEEDS = List.of("0.25x", "0.5x", "1x", "2x", "4x", "8x");
    /** What an arrow key moves the replay by: a second, which the label shows. */
    static final int STEP_MILLIS = 1000;

    final JButton play = new JButton("Pause");
    final JComboBox<String> speed = new JComboBox<>(SPEEDS.toArray(String[]::new));
    final JLabel time = new JLabel(text(0, 0));
    final JSlider slider = new JSlider(0, 0, 0);
    private Replay replay;
    /** True while {@link #follow} sets the components, whose listeners must then not act. */
    private boolean following;

    ReplayBar() {
        super(new BorderLayout(8, 0));
        setName("replayBar");
        play.setName("replayPlay");
        play.setToolTipText("Pause or play the replay (REPLAY {State Pause|Play})");
        speed.setName("replaySpeed");
        speed.setToolTipText("How fast the replay runs: 1x as recorded (REPLAY {Speed x})");
        time.setName("replayTime");
        time.setToolTipText("Where the replay is / the recording's length");
        slider.setName("replaySlider");
        slider.setToolTipText("Click or drag to jump to a time of the recording, arrow keys by a second (REPLAY {Time s})");
        play.setPreferredSize(new Dimension(Math.max(play.getPreferredSize().width, new JButton("Play").getPreferredSize().width),
                play.getPreferredSize().height));
        JPanel left = new JPanel(new FlowLayout(FlowLayout.LEFT, 6, 0));
        left.add(play);
        left.add(new JLabel("Speed:"));
        left.add(speed);
        left.add(time);
        add(left, BorderLayout.WEST);
        add(slider, BorderLayout.CENTER);
        setBorder(BorderFactory.createEmptyBorder(4, 0, 0, 0));
        setVisible(false);
        play.addActionListener(e -> playOrPause());
        speed.addActionListener(e -> speedChosen());
        slider.addChangeListener(e -> sliderMoved());
        clickJumpsThere();
        arrowsStepBy(STEP_MILLIS);
    }

    /**
     * A click on the track puts the knob where it was clicked, and the replay jumps there at the
     * release (the knob can be dragged on before it); the look's own click moves it by a step.
     */
    private void clickJumpsThere() {
        if (!(slider.getUI() instanceof BasicSliderUI ui)) {
            return;
        }
        MouseListener[] theLooks = slider.getMouseListeners();
        for (MouseListener listener : theLooks) {
            slider.removeMouseListener(listener);
        }
        // First, before the look's: its press then finds the knob under the mouse and drags it.
        slider.addMouseListener(new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                if (replay != null && slider.isEnabled() && SwingUtilities.isLeftMouseButton(e)) {
                    slider.setValueIsAdjusting(true);
                    slider.setValue(ui.valueForXPosition(e.getX()));
                }
            }

            @Override
            public void mouseReleased(MouseEvent e) {
                slider.setValueIsAdjusting(false);
            }
        });
        for (MouseListener listener : theLooks) {
            slider.addMouseListener(listener);
        }
    }

    /** The arrow keys move the replay by {@code millis} (the look's own step is a millisecond, nothing visible). */
    private void arrowsStepBy(int millis) {
        ActionMap actions = slider.getActionMap();
        actions.put("positiveUnitIncrement", step(millis));
        actions.put("negativeUnitIncrement", step(-millis));
    }

    private Action step(int millis) {
        return new AbstractAction() {
            @Override
            public void actionPerformed(ActionEvent e) {
                slider.setValue(Math.max(slider.getMinimum(), Math.min(slider.getMaximum(), slider.getValue() + millis)));
            }
        };
    }

    /** Shows the bar for this replay (null: hides it). */
    void attach(Replay controls) {
        replay = controls;
        setVisible(controls != null);
        if (controls != null) {
            follow();
        }
    }

    /** The server stopped: the bar goes. */
    void detach() {
        attach(null);
    }

    /** Shows where the replay is now; the window calls it at every refresh. A knob being dragged is left alone. */
    void follow() {
        if (replay == null) {
            return;
        }
        following = true;
        try {
            int duration = millis(replay.durationSeconds());
            if (slider.getMaximum() != duration) {
                slider.setMaximum(duration);
            }
            play.setText(replay.playing() ? "Pause" : "Play");
            int index = SPEEDS.indexOf(speedText(replay.speed()));
            if (speed.getSelectedIndex() != index) {
                speed.setSelectedIndex(index); // -1 (none) for a speed the list has not, set by REPLAY
            }
            if (!slider.getValueIsAdjusting()) {
                slider.setValue(millis(replay.timeSeconds()));
                time.setText(text(replay.timeSeconds(), replay.durationSeconds()));
            }
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, "the replay failed to say where it is: " + e, e);
        } finally {
            following = false;
        }
    }

    private void playOrPause() {
        if (replay == null) {
            return;
        }
        if (replay.playing()) {
            replay.pause();
        } else {
            replay.play();
        }
        follow();
    }

    private void speedChosen() {
        if (following || replay == null || speed.getSelectedIndex() < 0) {
            return;
        }
        String chosen = (String) speed.getSelectedItem();
        replay.speed(Double.parseDouble(chosen.substring(0, chosen.length() - 1)));
        follow();
    }

    /** While dragged, the time follows the knob; on release (or a click, a key), the replay jumps there. */
    private void sliderMoved() {
        if (following || replay == null) {
            return;
        }
        double seconds = Math.min(slider.getValue() / 1000.0, replay.durationSeconds());
        time.setText(text(seconds, replay.durationSeconds()));
        if (!slider.getValueIsAdjusting()) {
            replay.jump(seconds);
            follow();
        }
    }

    private static int millis(double seconds) {
        return (int) Math.max(0, Math.min(Integer.MAX_VALUE, Math.round(seconds * 1000)));
    }

    /** {@code 4x}, {@code 0.25x}: as the list writes a speed. */
    static String speedText(double times) {
        return Decimals.plain(times) + "x";
    }

    /** {@code 01:05 / 12:00}: the time and the duration in whole minutes and seconds (minutes past 99 as they are). */
    static String text(double seconds, double duration) {
        return clock(seconds) + " / " + clock(duration);
    }

    private static String clock(double seconds) {
        long whole = (long) Math.floor(Math.max(0, seconds));
        return String.format(Locale.ROOT, "%02d:%02d", whole / 60, whole % 60);
    }
}
