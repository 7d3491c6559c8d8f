package org.usarsim.wss.app;

import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;

import java.awt.event.WindowEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.CountDownLatch;
import java.util.logging.Logger;
import java.util.prefs.Preferences;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JSlider;
import javax.swing.JTextField;
import org.usarsim.wss.bench.ControlClient;
import org.usarsim.wss.bench.ReplayBenchmark;
import org.usarsim.wss.gui.Launch;
import org.usarsim.wss.gui.MainWindow;
import org.usarsim.wss.gui.ModelPreferences;
import org.usarsim.wss.gui.TestPreferences;
import org.usarsim.wss.gui.WindowLog;
import org.usarsim.wss.gui.WindowPreferences;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.replay.ReplayPropagationModel;
import org.usarsim.wss.protocol.Replies;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingReader;

/**
 * Issue 17, item 7 (docs/performance.md, "Recording and replay"): the seconds to open a 30-minute
 * recording of 12 robots polled 5 times a second in the window and to jump to its end. The
 * recording is written as {@code ReplayBenchmark --only size} writes it; the window is the real
 * one (under Xvfb), its model the replay. Measured: from the click on Start to the time bar showing
 * the recording's length (the model has read the file, the server listens); then, with the 12
 * robots registered, from the slider's release at its end to the bar at 30:00 and Robot1's GETSS
 * of Robot2 answering the strength of the last poll.
 *
 * <pre>
 * xvfb-run -a java -cp target/classes:target/test-classes org.usarsim.wss.app.ReplayWindowBenchmark [--runs 3] [--gz]
 * </pre>
 */
public final class ReplayWindowBenchmark {

    private ReplayWindowBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        int runs = 3;
        boolean gz = false;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--runs" -> runs = Integer.parseInt(args[++i]);
                case "--gz" -> gz = true;
                default -> throw new IllegalArgumentException("unknown argument " + args[i]);
            }
        }
        System.out.printf("WSS replay window benchmark: %d cores, %s, %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name") + " " + System.getProperty("java.version"), java.time.LocalDateTime.now());
        Path dir = Files.createTempDirectory("wss-replay-window");
        Path plain = dir.resolve("thirty.rec");
        Path gzip = dir.resolve("thirty.rec.gz");
        ReplayBenchmark.writeRun(plain, gzip, 12, 5, 5 * 60 * 30);
        Path file = gz ? gzip : plain;
        System.out.printf(Locale.ROOT, "  %s: %,d bytes, 12 robots, 9,000 polls, 30:00%n", file.getFileName(), Files.size(file));
        Recording recording = RecordingReader.read(file);
        Entry.Poll last = recording.polls().get(recording.polls().size() - 1);
        double lastStrength = last.pairs().stream().filter(p -> p.first().equals("Robot1") && p.second().equals("Robot2"))
                .mapToDouble(ModelPoll.Pair::strength).findFirst().orElseThrow();
        for (int run = 1; run <= runs; run++) {
            once(run, file, lastStrength);
        }
        Files.delete(plain);
        Files.delete(gzip);
        Files.delete(dir);
        System.exit(0);
    }

    private static void once(int run, Path file, double lastStrength) throws Exception {
        Preferences preferences = TestPreferences.create();
        WindowLog windowLog = new WindowLog();
        Logger.getLogger("").addHandler(windowLog);
        Properties properties = new Properties();
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        WindowServers servers = new WindowServers(ConfigFile.of(properties, "benchmark"));
        Launch launch = new Launch("0", "ReplayPropagationModel", false,
                new ModelSettings(Map.of("replay.file", file.toString())), false);
        List<ModelProvider> providers = List.of(ModelProvider.of(NoopPropagationModel::new),
                ModelProvider.of(ReplayPropagationModel::new));
        CountDownLatch closed = new CountDownLatch(1);
        JFrame frame = onEdt(() -> MainWindow.open(servers, providers, new WindowPreferences(preferences.node("window")),
                new ModelPreferences(preferences.node("models")), windowLog, launch, closed::countDown).frame());
        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        JLabel time = onEdt(() -> find(frame.getContentPane(), JLabel.class, "replayTime"));
        JSlider slider = onEdt(() -> find(frame.getContentPane(), JSlider.class, "replaySlider"));
        JTextField port = onEdt(() -> find(frame.getContentPane(), JTextField.class, "port"));

        long clicked = System.nanoTime();
        run(start::doClick);
        await(() -> onEdt(() -> time.isShowing() && time.getText().endsWith("/ 30:00")));
        double open = (System.nanoTime() - clicked) / 1e9;

        int controlPort = Integer.parseInt(onEdt(port::getText).strip());
        List<ControlClient> robots = new ArrayList<>();
        for (int i = 1; i <= 12; i++) {
            robots.add(new ControlClient(controlPort, "Robot" + i, 5000));
        }
        String wanted = Replies.signal("Robot2", lastStrength);
        long released = System.nanoTime();
        run(() -> {
            slider.setValueIsAdjusting(true);
            slider.setValue(slider.getMaximum());
            slider.setValueIsAdjusting(false);
        });
        await(() -> onEdt(time::getText).equals("30:00 / 30:00") && robots.get(0).ask("GETSS {Robot Robot2}").equals(wanted));
        double jump = (System.nanoTime() - released) / 1e9;
        System.out.printf(Locale.ROOT, "  run %d: open (Start to the bar at 00:00 / 30:00) %.3f s; jump to the end (release to"
                + " 30:00 / 30:00 and the last poll's GETSS) %.3f s; together %.3f s%n", run, open, jump, open + jump);
        for (ControlClient robot : robots) {
            robot.close();
        }
        run(() -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
        closed.await();
        Logger.getLogger("").removeHandler(windowLog);
        TestPreferences.remove(preferences);
    }

    private interface Check {
        boolean holds() throws Exception;
    }

    /** Polls the condition every millisecond, for at most 60 s. */
    private static void await(Check check) throws Exception {
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (!check.holds()) {
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException("not within 60 s");
            }
            Thread.sleep(1);
        }
    }
}
