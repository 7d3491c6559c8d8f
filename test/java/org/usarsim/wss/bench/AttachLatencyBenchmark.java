package org.usarsim.wss.bench;

import java.net.InetAddress;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.prefs.Preferences;
import javax.swing.JFrame;
import javax.swing.JTable;
import javax.swing.SwingUtilities;
import javax.swing.table.TableModel;
import org.usarsim.wss.attach.MonitorClient;
import org.usarsim.wss.gui.Gui;
import org.usarsim.wss.gui.MainWindow;
import org.usarsim.wss.gui.TestPreferences;
import org.usarsim.wss.gui.WindowPreferences;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.monitor.MonitorConfig;
import org.usarsim.wss.monitor.MonitorServer;
import org.usarsim.wss.monitor.Watched;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * A pair change to an attached window's table (issue 33, docs/performance.md): a hub (Noop model,
 * 127.0.0.1) with its monitor endpoint, a window attached to it over loopback (the real
 * {@link MonitorClient} and {@link MainWindow}), two robots registered; then the pair is forced
 * down and released in turn, each change timed from the hub's call to the moment the attached
 * window's Link statistics table holds the new state (a listener on the table's model, on the
 * event thread), the changes 0 to 150 ms apart (drawn, seeded), so that they come at any point of
 * the monitor's 100 ms comparisons as a run's changes do. Prints the median, p99 and max over the changes, and PASS when the p99 is under
 * 250 ms. Needs a display (Xvfb).
 *
 * <pre>
 * xvfb-run -a java -cp $CP org.usarsim.wss.bench.AttachLatencyBenchmark [--changes 300]
 * </pre>
 */
public final class AttachLatencyBenchmark {

    static final double P99_BOUND_MS = 250;
    private static final String TOKEN = "bench-operator-token-0123456789";

    public static void main(String[] args) throws Exception {
        int changes = args.length == 2 && args[0].equals("--changes") ? Integer.parseInt(args[1]) : 300;
        Path dir = Files.createTempDirectory("wss-attach-bench");
        Path tokens = dir.resolve("tokens");
        Files.writeString(tokens, "operator " + TOKEN + "\n");
        Files.setPosixFilePermissions(tokens, PosixFilePermissions.fromString("rw-------"));
        NoopPropagationModel model = new NoopPropagationModel();
        Hub hub = new Hub(TestHub.config(true, 65536, 600, 1000, 30), model);
        hub.start();
        MonitorServer monitor = MonitorServer.open(new MonitorConfig(-1, InetAddress.getLoopbackAddress(), tokens,
                MonitorConfig.DEFAULT_MAX_CLIENTS, null, null), new Watched(hub, model, Map.of(), ShapingConfig.OFF, "127.0.0.1"));
        monitor.start();
        Preferences preferences = TestPreferences.create();
        MonitorClient client = MonitorClient.connect(URI.create("http://127.0.0.1:" + monitor.port()), TOKEN, null);
        CountDownLatch closed = new CountDownLatch(1);
        JFrame frame = Gui.onEdt(() -> MainWindow.openAttached(client, new WindowPreferences(preferences.node("window")),
                closed::countDown).frame());
        JTable stats = Gui.onEdt(() -> Gui.find(frame.getContentPane(), JTable.class, "stats"));
        AtomicReference<String> wanted = new AtomicReference<>("up");
        AtomicReference<CountDownLatch> seen = new AtomicReference<>(new CountDownLatch(1));
        AtomicLong seenAt = new AtomicLong();
        Gui.run(() -> stats.getModel().addTableModelListener(e -> {
            if (wanted.get().equals(stateOf(stats.getModel())) && seen.get().getCount() > 0) {
                seenAt.set(System.nanoTime());
                seen.get().countDown();
            }
        }));
        long[] latencies = new long[changes];
        try (TestRobot r1 = new TestRobot(hub.controlPort(), "127.0.0.2"); TestRobot r2 = new TestRobot(hub.controlPort(), "127.0.0.3")) {
            r1.initAccepting("r1");
            r2.initAccepting("r2");
            r1.dns("r2", 0);
            if (!seen.get().await(10, TimeUnit.SECONDS)) {
                throw new IllegalStateException("the attached window never showed the pair up");
            }
            java.util.Random random = new java.util.Random(33);
            for (int i = 0; i < changes; i++) {
                // A change comes at any time, not just after the monitor's last comparison (it compares every 100 ms).
                Thread.sleep(random.nextInt(150));
                boolean down = i % 2 == 0;
                seen.set(new CountDownLatch(1));
                wanted.set(down ? "forced down" : "up");
                long start = System.nanoTime();
                if (down) {
                    hub.force("r1", "r2", Force.DOWN);
                } else {
                    hub.release("r1", "r2");
                }
                if (!seen.get().await(10, TimeUnit.SECONDS)) {
                    throw new IllegalStateException("change " + i + " (" + wanted.get() + ") never reached the table");
                }
                latencies[i] = seenAt.get() - start;
            }
        }
        double p50 = RelayBenchmark.percentile(latencies.clone(), 50) / 1e6;
        double p99 = RelayBenchmark.percentile(latencies.clone(), 99) / 1e6;
        double max = java.util.Arrays.stream(latencies).max().orElse(0) / 1e6;
        System.out.printf(Locale.ROOT, "pair change -> attached window's table, %d changes: median %.1f ms, p99 %.1f ms %s (< %.0f ms), max %.1f ms%n",
                changes, p50, p99, p99 < P99_BOUND_MS ? "PASS" : "FAIL", P99_BOUND_MS, max);
        SwingUtilities.invokeLater(() -> frame.dispatchEvent(new java.awt.event.WindowEvent(frame, java.awt.event.WindowEvent.WINDOW_CLOSING)));
        closed.await(10, TimeUnit.SECONDS);
        monitor.close();
        hub.close();
        TestPreferences.remove(preferences);
        System.exit(p99 < P99_BOUND_MS ? 0 : 1);
    }

    /** The state of the pair r1 - r2 in the statistics table's model, or "" when it has no row. */
    private static String stateOf(TableModel model) {
        for (int row = 0; row < model.getRowCount(); row++) {
            if ("r1".equals(model.getValueAt(row, 0)) && "r2".equals(model.getValueAt(row, 1))) {
                return String.valueOf(model.getValueAt(row, 2));
            }
        }
        return "";
    }
}
