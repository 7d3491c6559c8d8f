package org.usarsim.wss.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.prefs.Preferences;
import java.util.stream.Collectors;
import javax.swing.JTable;
import javax.swing.SwingUtilities;
import org.usarsim.wss.gui.HubServers;
import org.usarsim.wss.gui.Launch;
import org.usarsim.wss.gui.MainWindow;
import org.usarsim.wss.gui.ModelPreferences;
import org.usarsim.wss.gui.WindowLog;
import org.usarsim.wss.gui.WindowPreferences;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/**
 * The window under load (docs/performance.md): robots register, then each opens a connection
 * through the WSS to an echo server, sends a message, reads it back and closes, as fast as it
 * can. Run once headless (the hub alone) and once with the main window open, in one JVM; prints
 * the connections per second of both, the event thread's round-trip latency while the window is
 * loaded (an invokeLater probe every 10 ms), and whether the window's tables equal the hub's own
 * state once the load stops. Needs a display (Xvfb).
 *
 * <pre>
 * xvfb-run -a java -cp target/classes:target/test-classes org.usarsim.wss.bench.WindowBenchmark [--seconds 30] [--robots 200]
 * xvfb-run -a java -cp target/classes:target/test-classes org.usarsim.wss.bench.WindowBenchmark --mesh 100 [--seconds 30]
 * </pre>
 *
 * <p>With {@code --mesh n}: n robots in full mesh, and the ports table sorted and filtered while
 * the probe runs ({@link #meshInTheWindow}).
 */
public final class WindowBenchmark {

    private static final int MESSAGE = 64;
    /** The robots of a window run, registered until its tables were checked (a socket nobody holds is closed by the GC). */
    private static final List<ControlClient> REGISTERED = new ArrayList<>();

    public static void main(String[] args) throws Exception {
        int seconds = 30;
        int robots = 200;
        int runs = 1;
        int mesh = 0;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--seconds" -> seconds = Integer.parseInt(args[++i]);
                case "--robots" -> robots = Integer.parseInt(args[++i]);
                case "--runs" -> runs = Integer.parseInt(args[++i]);
                case "--mesh" -> mesh = Integer.parseInt(args[++i]);
                default -> throw new IllegalArgumentException("unknown argument " + args[i]);
            }
        }
        if (mesh > 0) {
            quietLog();
            meshInTheWindow(mesh, seconds);
            System.exit(0);
        }
        System.out.printf("WSS window benchmark: %d cores, %s, %d robots, %d s each run, %s%n",
                Runtime.getRuntime().availableProcessors(), System.getProperty("java.vm.name") + " " + System.getProperty("java.version"),
                robots, seconds, java.time.LocalDateTime.now());
        quietLog();
        // Alternating, so that neither always runs on a warmer JVM or a busier machine.
        List<Double> headless = new ArrayList<>();
        List<Double> window = new ArrayList<>();
        for (int run = 0; run < runs; run++) {
            if (run % 2 == 0) {
                headless.add(headless(robots, seconds));
                window.add(withWindow(robots, seconds));
            } else {
                window.add(withWindow(robots, seconds));
                headless.add(headless(robots, seconds));
            }
        }
        System.out.printf(Locale.ROOT, "%nconnections per second, median of %d runs: headless %.0f, window open %.0f (window/headless %.2f)%n",
                runs, median(headless), median(window), median(window) / median(headless));
        System.exit(0);
    }

    /** The server's log as headless mode writes it (to standard output; here to nowhere). */
    private static void quietLog() {
        java.util.logging.Logger root = java.util.logging.Logger.getLogger("");
        for (java.util.logging.Handler handler : root.getHandlers()) {
            root.removeHandler(handler);
        }
        root.addHandler(new java.util.logging.StreamHandler(OutputStream.nullOutputStream(), new java.util.logging.SimpleFormatter()));
        root.setLevel(java.util.logging.Level.INFO);
    }

    /**
     * The window with robots in full mesh (issue 18): n robots register and every one asks DNS
     * for every other, so the ports table holds n(n-1) rows and the statistics table n(n-1)/2;
     * then, for the given time, the ports table is sorted by each column in turn (both ways) and
     * filtered (a pattern typed, then cleared) every 250 ms, as a person would, while a probe
     * measures the event thread's round trip.
     */
    private static void meshInTheWindow(int robots, int seconds) throws Exception {
        Preferences preferences = Preferences.userRoot().node("wss-bench-" + System.nanoTime());
        WindowLog windowLog = new WindowLog();
        java.util.logging.Logger.getLogger("").addHandler(windowLog);
        HubServers servers = new HubServers(config().withMaxPortsPerAddress(Math.max(HubConfig.MAX_PORTS_PER_ADDRESS, robots * (robots - 1))));
        List<Hub> hubs = servers.hubs();
        CountDownLatch closed = new CountDownLatch(1);
        MainWindow[] window = new MainWindow[1];
        SwingUtilities.invokeAndWait(() -> window[0] = MainWindow.open(servers, List.of(ModelProvider.of(NoopPropagationModel::new)),
                new WindowPreferences(preferences), new ModelPreferences(preferences.node("models")), windowLog,
                new Launch("0", null, false, null, true), closed::countDown));
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (hubs.isEmpty() && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        Hub hub = hubs.get(0);
        Probe forming = new Probe();
        forming.start();
        for (int i = 0; i < robots; i++) {
            REGISTERED.add(new ControlClient(hub.controlPort(), "R" + i, 5000));
        }
        long start = System.nanoTime();
        List<Thread> asking = new ArrayList<>();
        for (int i = 0; i < robots; i++) {
            ControlClient client = REGISTERED.get(i);
            int from = i;
            Thread thread = new Thread(() -> {
                for (int to = 0; to < robots; to++) {
                    if (to != from) {
                        try {
                            client.dns("R" + to);
                        } catch (IOException e) {
                            System.out.println("  DNS refused: " + e.getMessage());
                        }
                    }
                }
            });
            thread.start();
            asking.add(thread);
        }
        for (Thread thread : asking) {
            thread.join();
        }
        int ports = robots * (robots - 1);
        JTable table = onEdt(() -> find(window[0].frame().getContentPane(), "ports"));
        while (onEdt(() -> table.getModel().getRowCount()) < ports) {
            Thread.sleep(20);
        }
        forming.stop();
        System.out.printf(Locale.ROOT, "%n%d robots, %d DNS in the window's hub, the table showing all %d ports %.1f s after the first DNS%n",
                robots, ports, ports, (System.nanoTime() - start) / 1e9);
        System.out.println("  event thread while the mesh formed: " + forming.summary());

        javax.swing.JTextField filter = onEdt(() -> findField(window[0].frame().getContentPane(), "portsFilter"));
        List<String> patterns = List.of("R1*", "R4? R7", "R9* R1?", "r5 r");
        Probe probe = new Probe();
        List<Long> sortMs = new ArrayList<>();
        List<Long> filterMs = new ArrayList<>();
        probe.start();
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        int round = 0;
        while (System.nanoTime() < end) {
            int column = round % table.getColumnCount();
            long sortStart = System.nanoTime();
            SwingUtilities.invokeAndWait(() -> table.getRowSorter().toggleSortOrder(column));
            sortMs.add((System.nanoTime() - sortStart) / 1_000_000);
            Thread.sleep(250);
            String pattern = round % 2 == 0 ? patterns.get(round / 2 % patterns.size()) : "";
            long filterStart = System.nanoTime();
            SwingUtilities.invokeAndWait(() -> filter.setText(pattern));
            filterMs.add((System.nanoTime() - filterStart) / 1_000_000);
            Thread.sleep(250);
            round++;
        }
        probe.stop();
        int shown = onEdt(() -> table.getRowCount());
        System.out.printf(Locale.ROOT, "  %d sorts (ms: median %d, max %d) and %d filters (ms: median %d, max %d) of the %d ports in %d s;"
                + " %d rows shown at the end%n", sortMs.size(), sortMs.stream().sorted().toList().get(sortMs.size() / 2),
                sortMs.stream().mapToLong(Long::longValue).max().orElse(0), filterMs.size(),
                filterMs.stream().sorted().toList().get(filterMs.size() / 2), filterMs.stream().mapToLong(Long::longValue).max().orElse(0),
                ports, seconds, shown);
        System.out.println("  event thread meanwhile: " + probe.summary());
        closeRobots();
        SwingUtilities.invokeLater(() -> window[0].frame().dispatchEvent(
                new java.awt.event.WindowEvent(window[0].frame(), java.awt.event.WindowEvent.WINDOW_CLOSING)));
        closed.await(10, TimeUnit.SECONDS);
        preferences.removeNode();
    }

    private static javax.swing.JTextField findField(java.awt.Container container, String name) {
        for (java.awt.Component child : container.getComponents()) {
            if (child instanceof javax.swing.JTextField field && name.equals(field.getName())) {
                return field;
            }
            if (child instanceof java.awt.Container inner) {
                javax.swing.JTextField found = findField(inner, name);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }

    private static double median(List<Double> values) {
        List<Double> sorted = values.stream().sorted().toList();
        return sorted.get(sorted.size() / 2);
    }

    private static HubConfig config() throws IOException {
        return TestHub.config(true, 65536, 600, 1000, 30);
    }

    private static double headless(int robots, int seconds) throws Exception {
        Hub hub = new Hub(config(), new NoopPropagationModel());
        hub.start();
        try {
            return load("headless", hub.controlPort(), robots, seconds);
        } finally {
            closeRobots();
            hub.close();
        }
    }

    private static double withWindow(int robots, int seconds) throws Exception {
        Preferences preferences = Preferences.userRoot().node("wss-bench-" + System.nanoTime());
        WindowLog windowLog = new WindowLog();
        java.util.logging.Logger.getLogger("").addHandler(windowLog);
        HubServers servers = new HubServers(config());
        List<Hub> hubs = servers.hubs();
        CountDownLatch closed = new CountDownLatch(1);
        MainWindow[] window = new MainWindow[1];
        SwingUtilities.invokeAndWait(() -> window[0] = MainWindow.open(servers, List.of(ModelProvider.of(NoopPropagationModel::new)),
                new WindowPreferences(preferences), new ModelPreferences(preferences.node("models")), windowLog,
                new Launch("0", null, false, null, true), closed::countDown));
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (hubs.isEmpty() && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        Hub hub = hubs.get(0);
        Probe probe = new Probe();
        probe.start();
        double rate = load("window open", hub.controlPort(), robots, seconds);
        probe.stop();
        System.out.println("  event thread round trip (invokeLater every 10 ms, during the load): " + probe.summary());

        // The load stopped and every robot is still registered: the tables must come to equal the hub.
        HubSnapshot truth = hub.snapshot();
        long start = System.nanoTime();
        boolean equal = false;
        while (!equal && System.nanoTime() - start < TimeUnit.SECONDS.toNanos(10)) {
            truth = hub.snapshot();
            HubSnapshot expected = truth;
            equal = onEdt(() -> tablesShow(window[0], expected));
            if (!equal) {
                Thread.sleep(20);
            }
        }
        System.out.printf(Locale.ROOT, "  tables equal to the hub's state after the load: %s (%d robots, %d ports, %d links; %.0f ms after the load stopped)%n",
                equal, truth.robots().size(), truth.ports().size(), truth.links().size(), (System.nanoTime() - start) / 1e6);
        closeRobots();
        SwingUtilities.invokeLater(() -> window[0].frame().dispatchEvent(
                new java.awt.event.WindowEvent(window[0].frame(), java.awt.event.WindowEvent.WINDOW_CLOSING)));
        closed.await(10, TimeUnit.SECONDS);
        preferences.removeNode();
        return rate;
    }

    private static void closeRobots() throws IOException {
        for (ControlClient client : REGISTERED) {
            client.close();
        }
        REGISTERED.clear();
    }

    private static boolean tablesShow(MainWindow window, HubSnapshot truth) {
        return rows(window, "robots").equals(truth.robots().stream()
                        .map(r -> List.of(r.name(), r.address(), r.ports().stream().map(String::valueOf).collect(Collectors.joining(",")),
                                "-")) // airtime: links not shaped
                        .toList())
                && rows(window, "ports").equals(truth.ports().stream()
                        .map(p -> List.of(p.from(), p.to(), String.valueOf(p.targetPort()), String.valueOf(p.wssPort()), p.listening() ? "yes" : "no"))
                        .toList())
                && rows(window, "links").equals(truth.links().stream()
                        .map(l -> List.of(l.from(), l.to(), String.valueOf(l.outgoingPort())))
                        .toList());
    }

    /** A table's rows in the model's order (the hub's snapshot order), each cell as text. Event thread. */
    private static List<List<String>> rows(MainWindow window, String name) {
        JTable table = find(window.frame().getContentPane(), name);
        List<List<String>> rows = new ArrayList<>();
        for (int row = 0; row < table.getModel().getRowCount(); row++) {
            List<String> cells = new ArrayList<>();
            for (int column = 0; column < table.getModel().getColumnCount(); column++) {
                cells.add(String.valueOf(table.getModel().getValueAt(row, column)));
            }
            rows.add(cells);
        }
        return rows;
    }

    private static JTable find(java.awt.Container container, String name) {
        for (java.awt.Component child : container.getComponents()) {
            if (child instanceof JTable table && name.equals(table.getName())) {
                return table;
            }
            if (child instanceof java.awt.Container inner) {
                JTable found = find(inner, name);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }

    private static <T> T onEdt(java.util.concurrent.Callable<T> call) throws Exception {
        Object[] result = new Object[1];
        Exception[] failure = new Exception[1];
        SwingUtilities.invokeAndWait(() -> {
            try {
                result[0] = call.call();
            } catch (Exception e) {
                failure[0] = e;
            }
        });
        if (failure[0] != null) {
            throw failure[0];
        }
        @SuppressWarnings("unchecked")
        T value = (T) result[0];
        return value;
    }

    /**
     * Registers the robots (robot i accepts on the echo server's port; its connections go to robot
     * i+1), then runs every robot's loop for the given time. Returns the connections per second.
     */
    private static double load(String label, int controlPort, int robots, int seconds) throws Exception {
        try (EchoServer echo = new EchoServer(MESSAGE, true)) {
            List<ControlClient> clients = new ArrayList<>();
            for (int i = 0; i < robots; i++) {
                clients.add(new ControlClient(controlPort, "robot" + i, echo.port()));
            }
            int[] wssPorts = new int[robots];
            for (int i = 0; i < robots; i++) {
                wssPorts[i] = clients.get(i).dns("robot" + ((i + 1) % robots));
            }
            AtomicLong done = new AtomicLong();
            AtomicLong failed = new AtomicLong();
            java.util.Set<String> reasons = java.util.concurrent.ConcurrentHashMap.newKeySet();
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
            List<Thread> threads = new ArrayList<>();
            for (int i = 0; i < robots; i++) {
                int wssPort = wssPorts[i];
                Thread thread = new Thread(null, () -> connectLoop(wssPort, end, done, failed, reasons), "robot " + i, 256 * 1024);
                thread.setDaemon(true);
                threads.add(thread);
            }
            long start = System.nanoTime();
            threads.forEach(Thread::start);
            for (Thread thread : threads) {
                thread.join();
            }
            double elapsed = (System.nanoTime() - start) / 1e9;
            double rate = done.get() / elapsed;
            System.out.printf(Locale.ROOT, "%n%s: %d connections (open, %d bytes there and back, close) in %.1f s: %.0f per second; %d failed%n",
                    label, done.get(), MESSAGE, elapsed, rate, failed.get());
            if (!reasons.isEmpty()) {
                System.out.println("  failures: " + reasons);
            }
            REGISTERED.addAll(clients);
            return rate;
        }
    }

    /**
     * One robot: connect, send a message, read its echo and the end of stream (the echo server
     * closes first, so that neither the robot nor the WSS's outgoing socket is left in TIME_WAIT and
     * a long run does not exhaust the ephemeral ports), close.
     */
    private static void connectLoop(int wssPort, long end, AtomicLong done, AtomicLong failed, java.util.Set<String> reasons) {
        byte[] message = new byte[MESSAGE];
        byte[] back = new byte[MESSAGE];
        while (System.nanoTime() < end) {
            try (Socket socket = new Socket("127.0.0.1", wssPort)) {
                socket.setTcpNoDelay(true);
                socket.setSoTimeout(10_000);
                socket.setSoLinger(true, 0); // the end of stream is read first: the reset only spares the TIME_WAIT
                OutputStream out = socket.getOutputStream();
                InputStream in = socket.getInputStream();
                out.write(message);
                if (in.readNBytes(back, 0, MESSAGE) != MESSAGE || !Arrays.equals(message, back)) {
                    throw new IOException("echo lost");
                }
                if (in.read() != -1) {
                    throw new IOException("more than the echo");
                }
                done.incrementAndGet();
            } catch (IOException e) {
                failed.incrementAndGet();
                if (reasons.size() < 5) {
                    reasons.add(e.toString());
                }
            }
        }
    }

    /** Posts a task to the event thread every 10 ms and records how long it took to run. */
    private static final class Probe {
        private final List<Long> latencies = new ArrayList<>();
        private volatile boolean running = true;
        private Thread thread;

        void start() {
            thread = new Thread(() -> {
                while (running) {
                    long posted = System.nanoTime();
                    SwingUtilities.invokeLater(() -> record(System.nanoTime() - posted));
                    try {
                        Thread.sleep(10);
                    } catch (InterruptedException e) {
                        return;
                    }
                }
            }, "edt-probe");
            thread.setDaemon(true);
            thread.start();
        }

        private synchronized void record(long nanos) {
            latencies.add(nanos);
        }

        void stop() throws InterruptedException {
            running = false;
            thread.join();
        }

        synchronized String summary() {
            long[] sorted = latencies.stream().mapToLong(Long::longValue).sorted().toArray();
            return String.format(Locale.ROOT, "%d probes, p50 %.2f ms, p99 %.2f ms, max %.2f ms", sorted.length,
                    sorted[sorted.length / 2] / 1e6, sorted[(int) (sorted.length * 0.99)] / 1e6, sorted[sorted.length - 1] / 1e6);
        }
    }
}
