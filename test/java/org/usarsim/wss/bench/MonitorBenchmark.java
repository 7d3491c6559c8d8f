package org.usarsim.wss.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The monitor's cost (issue 33, docs/performance.md): the WSS as its own process with
 * {@code --robots} robots in full mesh (every DNS asked) and {@code --connections} connections
 * through it, each written as fast as it goes; phases of {@code --phase} seconds alternate between
 * no viewer and {@code --viewers} viewers (each a {@code curl -N} of GET /api/events, a process of
 * its own), the order swapped every pair; the bytes forwarded in each phase and their ratio, and the
 * CPU of the server's monitor threads per viewer. Then a viewer stopped with SIGSTOP for
 * {@code --stop} seconds beside the others: the server's heap, whether it was cut, whether the
 * others kept receiving. The server runs with {@code -Dwss.monitor.lingerMs=0}: with no viewer it
 * stops comparing at once, as it would a minute after the last.
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.MonitorBenchmark --robots 100 --connections 200 --pairs 5
 * </pre>
 */
public final class MonitorBenchmark {

    private static final String TOKEN = "bench-viewer-token-0123456789abcdef";
    private static final Pattern MONITOR = Pattern.compile("monitor listening on http://[^:]+:(\\d+)");

    private final AtomicLong received = new AtomicLong();
    private int monitorPort;

    private MonitorBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        int robots = 100;
        int connections = 200;
        int phase = 10;
        int pairs = 5;
        int viewers = 8;
        int stop = 60;
        String only = "all";
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--robots" -> robots = Integer.parseInt(args[++i]);
                case "--connections" -> connections = Integer.parseInt(args[++i]);
                case "--phase" -> phase = Integer.parseInt(args[++i]);
                case "--pairs" -> pairs = Integer.parseInt(args[++i]);
                case "--viewers" -> viewers = Integer.parseInt(args[++i]);
                case "--stop" -> stop = Integer.parseInt(args[++i]);
                case "--only" -> only = args[++i];
                default -> throw new IllegalArgumentException("unknown option " + args[i]);
            }
        }
        new MonitorBenchmark().run(robots, only.equals("stop") ? 0 : connections, phase, only.equals("stop") ? 0 : pairs, viewers,
                only.equals("forwarding") ? 0 : stop);
    }

    private void run(int robots, int connections, int phase, int pairs, int viewers, int stop) throws Exception {
        Path tokens = Files.createTempFile("wss-bench-tokens", "");
        Files.setPosixFilePermissions(tokens, PosixFilePermissions.fromString("rw-------"));
        Files.writeString(tokens, "viewer " + TOKEN + "\n");
        tokens.toFile().deleteOnExit();
        System.setProperty("wss.bench.jvmOptions", (System.getProperty("wss.bench.jvmOptions", "") + " -Dwss.monitor.lingerMs=0").trim());
        try (WssProcess wss = WssProcess.start("wss.maxPortsPerAddress=" + Math.max(10_000, robots * (robots - 1)),
                "wss.monitor.port=-1", "wss.monitor.tokens=" + tokens, "wss.monitor.maxClients=16")) {
            Matcher port = MONITOR.matcher(String.valueOf(awaitLine(wss, "monitor listening on")));
            if (!port.find()) {
                throw new IOException("the monitor did not start");
            }
            monitorPort = Integer.parseInt(port.group(1));
            List<ServerSocket> accepting = new ArrayList<>();
            List<ControlClient> clients = new ArrayList<>();
            for (int i = 0; i < robots; i++) {
                ServerSocket socket = new ServerSocket(0, 200, InetAddress.getLoopbackAddress());
                accepting.add(socket);
                acceptForever(socket);
                clients.add(new ControlClient(wss.controlPort, "R" + i, socket.getLocalPort()));
            }
            MeshAsker.Answers mesh = MeshAsker.askAll(clients, "R");
            System.out.printf(Locale.ROOT, "  %d robots, %d DNS in %.1f s (%d refused)%n", robots, robots * (robots - 1), mesh.seconds(),
                    mesh.refused());
            List<Socket> senders = new ArrayList<>();
            int opened = 0;
            for (int k = 0; opened < connections && k < robots * robots; k++) {
                int i = (k * 7) % robots;
                int j = (k * 13 + 1) % robots;
                if (i != j && mesh.ports()[i][j] > 0) {
                    Socket sender = new Socket(InetAddress.getLoopbackAddress(), mesh.ports()[i][j]);
                    senders.add(sender);
                    writeForever(sender);
                    opened++;
                }
            }
            System.out.printf(Locale.ROOT, "  %d connections written as fast as they go; phases of %d s%n", opened, phase);
            Thread.sleep(3000); // every link up and forwarding
            List<Double> ratios = new ArrayList<>();
            List<Double> perViewerMs = new ArrayList<>();
            for (int p = 0; p < pairs; p++) {
                boolean viewersFirst = p % 2 == 1;
                double none = 0;
                double with = 0;
                for (int half = 0; half < 2; half++) {
                    boolean watched = (half == 0) == viewersFirst;
                    List<Process> curls = watched ? viewers(viewers, null) : List.of();
                    Thread.sleep(watched ? 2000 : 1000); // snapshots sent / the publisher idle
                    long bytes = received.get();
                    long monitorCpu = ProcessStats.threadCpuNanos(wss.pid(), "wss-monitor");
                    long start = System.nanoTime();
                    Thread.sleep(TimeUnit.SECONDS.toMillis(phase));
                    double seconds = (System.nanoTime() - start) / 1e9;
                    double rate = (received.get() - bytes) / seconds;
                    double monitorMs = (ProcessStats.threadCpuNanos(wss.pid(), "wss-monitor") - monitorCpu) / 1e6 / seconds;
                    end(curls);
                    if (watched) {
                        with = rate;
                        perViewerMs.add(monitorMs / viewers);
                    } else {
                        none = rate;
                    }
                    System.out.printf(Locale.ROOT, "  pair %d, %-10s forwarded %7.1f MB/s; monitor threads %6.1f ms CPU/s%n", p + 1,
                            watched ? viewers + " viewers" : "no viewer", rate / 1e6, monitorMs);
                }
                ratios.add(with / none);
            }
            if (pairs > 0) {
                System.out.println("  forwarding with " + viewers + " viewers / none: "
                        + new PairedRatios(ratios.stream().mapToDouble(Double::doubleValue).toArray()).summary());
                System.out.printf(Locale.ROOT, "  monitor CPU per viewer: median %.2f ms/s (%s)%n", median(perViewerMs), perViewerMs);
            }
            if (stop > 0) {
                for (Socket sender : senders) {
                    sender.close();
                }
                stopped(wss, viewers, stop, clients.size());
            }
            for (Socket sender : senders) {
                sender.close();
            }
            for (ControlClient client : clients) {
                client.close();
            }
        }
    }

    /** A viewer stopped with SIGSTOP beside {@code viewers} others: the heap, the cut, the others' bytes. */
    private void stopped(WssProcess wss, int viewers, int seconds, int robots) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (metric("wss_monitor_streams") > 0 && System.nanoTime() < deadline) {
            Thread.sleep(500); // the last phase's streams end at their next write (a keepalive within 15 s)
        }
        Flapping flapping = new Flapping(wss.controlPort, robots);
        flapping.start();
        Path dir = Files.createTempDirectory("wss-bench-viewers");
        List<Process> others = viewers(viewers, dir);
        Process frozen = viewers(1, null).get(0);
        Thread.sleep(2000);
        long heapBefore = heapUsedKiB(wss.pid(), true);
        new ProcessBuilder("kill", "-STOP", Long.toString(frozen.pid())).start().waitFor();
        System.out.printf(Locale.ROOT, "  viewer %d stopped (SIGSTOP) for %d s beside %d others; heap after a GC before: %d MiB%n",
                frozen.pid(), seconds, viewers, heapBefore / 1024);
        long maxHeap = 0;
        long[] sizes = sizes(dir, viewers);
        int starved = 0;
        long cutAt = -1;
        long start = System.nanoTime();
        for (int s = 5; s <= seconds; s += 5) {
            Thread.sleep(5000);
            maxHeap = Math.max(maxHeap, heapUsedKiB(wss.pid(), false));
            long[] now = sizes(dir, viewers);
            for (int v = 0; v < viewers; v++) {
                if (now[v] == sizes[v]) {
                    starved++;
                }
            }
            sizes = now;
            if (cutAt < 0 && metric("wss_monitor_streams_cut_total") > 0) {
                cutAt = (System.nanoTime() - start) / 1_000_000_000L;
            }
        }
        long heapAfter = heapUsedKiB(wss.pid(), true);
        System.out.printf(Locale.ROOT, "  during the stop: heap in use at most %d MiB (sampled every 5 s, no GC forced), after a GC %d MiB;"
                + " the stopped viewer cut %s; 5 s windows in which another viewer got nothing: %d of %d%n", maxHeap / 1024, heapAfter / 1024,
                cutAt < 0 ? "NOT" : "within " + cutAt + " s", starved, viewers * (seconds / 5));
        System.out.printf(Locale.ROOT, "  metrics: streams %d, cut %d, events dropped %d%n", metric("wss_monitor_streams"),
                metric("wss_monitor_streams_cut_total"), metric("wss_monitor_events_dropped_total"));
        flapping.stop();
        System.out.printf(Locale.ROOT, "  meanwhile an operator forced %d pairs down and back, %d FORCEs%n", Flapping.PAIRS, flapping.forces());
        new ProcessBuilder("kill", "-CONT", Long.toString(frozen.pid())).start().waitFor();
        boolean ended = frozen.waitFor(10, TimeUnit.SECONDS);
        System.out.println("  resumed (SIGCONT): its stream " + (ended ? "had ended (curl exited " + frozen.exitValue() + ")" : "still open"));
        end(others);
        end(List.of(frozen));
    }

    /**
     * A busy hub for the stopped viewer's test: an operator on the control port forces
     * {@link #PAIRS} pairs down and back up every 100 ms, so that every comparison has ports,
     * pairs and lines to tell.
     */
    private static final class Flapping implements Runnable {
        static final int PAIRS = 100;
        private final ControlClient operator;
        private final int robots;
        private final Thread thread = new Thread(this, "flapping");
        private volatile boolean running = true;
        private long forces;

        Flapping(int controlPort, int robots) throws IOException {
            this.operator = ControlClient.operator(controlPort);
            this.robots = robots;
        }

        void start() {
            thread.setDaemon(true);
            thread.start();
        }

        void stop() throws Exception {
            running = false;
            thread.join();
            operator.close();
        }

        long forces() {
            return forces;
        }

        @Override
        public void run() {
            boolean down = true;
            try {
                while (running) {
                    for (int k = 0; k < PAIRS; k++) {
                        operator.ask("FORCE {Robot R" + k % robots + "} {Peer R" + (k + 1) % robots + "} {State " + (down ? "Down" : "Model") + "}");
                        forces++;
                    }
                    down = !down;
                    Thread.sleep(100);
                }
            } catch (Exception e) {
                System.out.println("  flapping ended: " + e);
            }
        }
    }

    private List<Process> viewers(int count, Path dir) throws IOException {
        List<Process> curls = new ArrayList<>();
        for (int v = 0; v < count; v++) {
            ProcessBuilder curl = new ProcessBuilder("curl", "-sN", "-H", "Authorization: Bearer " + TOKEN,
                    "http://127.0.0.1:" + monitorPort + "/api/events");
            curl.redirectOutput(dir == null ? ProcessBuilder.Redirect.DISCARD : ProcessBuilder.Redirect.to(dir.resolve("v" + v).toFile()));
            curl.redirectError(ProcessBuilder.Redirect.DISCARD);
            curls.add(curl.start());
        }
        return curls;
    }

    private static long[] sizes(Path dir, int viewers) throws IOException {
        long[] sizes = new long[viewers];
        for (int v = 0; v < viewers; v++) {
            sizes[v] = Files.size(dir.resolve("v" + v));
        }
        return sizes;
    }

    private static void end(List<Process> curls) throws InterruptedException {
        for (Process curl : curls) {
            curl.destroy();
        }
        for (Process curl : curls) {
            curl.waitFor(5, TimeUnit.SECONDS);
        }
    }

    private long metric(String name) throws Exception {
        HttpResponse<String> metrics = HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + monitorPort
                + "/metrics")).header("Authorization", "Bearer " + TOKEN).build(), HttpResponse.BodyHandlers.ofString());
        for (String line : metrics.body().split("\n")) {
            if (line.startsWith(name + " ")) {
                return (long) Double.parseDouble(line.substring(name.length() + 1));
            }
        }
        return -1;
    }

    /** The heap in use, in KiB: after a full GC, or as it is. */
    private static long heapUsedKiB(long pid, boolean gc) throws IOException, InterruptedException {
        if (gc) {
            return CpuRun.heapAfterGc(pid);
        }
        Matcher matcher = CpuRun.USED.matcher(CpuRun.run("jcmd", Long.toString(pid), "GC.heap_info"));
        return matcher.find() ? Long.parseLong(matcher.group(1)) : -1;
    }

    private static String awaitLine(WssProcess wss, String text) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (System.nanoTime() < deadline) {
            String line = wss.lastLineContaining(text);
            if (line != null) {
                return line;
            }
            Thread.sleep(50);
        }
        return null;
    }

    private void acceptForever(ServerSocket socket) {
        daemon("accept", () -> {
            while (true) {
                Socket accepted = socket.accept();
                daemon("read", () -> {
                    byte[] buffer = new byte[64 * 1024];
                    try (InputStream in = accepted.getInputStream()) {
                        int read;
                        while ((read = in.read(buffer)) >= 0) {
                            received.addAndGet(read);
                        }
                    }
                });
            }
        });
    }

    private static void writeForever(Socket socket) {
        daemon("write", () -> {
            byte[] chunk = new byte[64 * 1024];
            try (OutputStream out = socket.getOutputStream()) {
                while (true) {
                    out.write(chunk);
                }
            }
        });
    }

    private interface Loop {
        void run() throws Exception;
    }

    private static void daemon(String name, Loop loop) {
        Thread thread = new Thread(() -> {
            try {
                loop.run();
            } catch (Exception e) {
                // the socket closed: the benchmark ends
            }
        }, name);
        thread.setDaemon(true);
        thread.start();
    }

    private static double median(List<Double> values) {
        List<Double> sorted = values.stream().sorted().toList();
        return sorted.isEmpty() ? Double.NaN : sorted.get(sorted.size() / 2);
    }
}
