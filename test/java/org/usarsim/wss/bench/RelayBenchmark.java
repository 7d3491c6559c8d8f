package org.usarsim.wss.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Measures the WSS against socat and direct loopback, in one run on one machine, and prints
 * the results as ratios. Needs socat and iperf3 on the PATH. See docs/performance.md.
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.RelayBenchmark [--seconds 5] [--runs 3] [--only NAME]
 * </pre>
 * NAME is one of throughput, latency, split, many, eventlog, counting; --baseline JAR adds a build
 * from before a change (a wss.jar or a classes folder) to the counting section.
 */
public final class RelayBenchmark {

    private static final Pattern RECEIVED_BPS = Pattern.compile("\"sum_received\"\\s*:\\s*\\{[^}]*\"bits_per_second\"\\s*:\\s*([0-9.eE+]+)");
    /** The CPU the iperf3 client and server used, in percent of one CPU over the run. */
    private static final Pattern CLIENT_CPU = Pattern.compile("\"host_total\"\\s*:\\s*([0-9.eE+]+)");
    private static final Pattern SERVER_CPU = Pattern.compile("\"remote_total\"\\s*:\\s*([0-9.eE+]+)");

    private final int seconds;
    private final int runs;
    private final List<Process> children = new ArrayList<>();

    private RelayBenchmark(int seconds, int runs) {
        this.seconds = seconds;
        this.runs = runs;
    }

    public static void main(String[] args) throws Exception {
        int seconds = 5;
        int runs = 3;
        String only = null;
        String baseline = null;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--seconds" -> seconds = Integer.parseInt(args[++i]);
                case "--runs" -> runs = Integer.parseInt(args[++i]);
                case "--only" -> only = args[++i];
                case "--baseline" -> baseline = args[++i];
                default -> throw new IllegalArgumentException("unknown argument " + args[i]);
            }
        }
        RelayBenchmark benchmark = new RelayBenchmark(seconds, runs);
        Runtime.getRuntime().addShutdownHook(new Thread(benchmark::killChildren));
        System.out.printf("WSS relay benchmark: %d cores, %s, %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name") + " " + System.getProperty("java.version"), java.time.LocalDateTime.now());
        if (only == null || only.equals("throughput")) {
            benchmark.throughput();
        }
        if (only == null || only.equals("latency")) {
            benchmark.latency();
        }
        if (only == null || only.equals("split")) {
            benchmark.splitWrites();
        }
        if (only == null || only.equals("many")) {
            benchmark.manyConnections();
        }
        if (only == null || only.equals("eventlog")) {
            benchmark.eventLog();
        }
        if (only == null || only.equals("counting")) {
            benchmark.counting(baseline);
        }
        if (only == null || only.equals("record")) {
            benchmark.recording();
        }
        benchmark.killChildren();
        System.exit(0);
    }

    // ---- throughput: iperf3 through each path ----

    private void throughput() throws Exception {
        System.out.printf("%n## Throughput of one stream (iperf3, %d s, median of %d runs)%n%n", seconds, runs);
        try (WssProcess wss = WssProcess.start(); WssProcess osBuffers = WssProcess.start("wss.socketBuffer=0");
                WssProcess wss2k = WssProcess.start("wss.chunkSize=2048")) {
            String[] names = {"direct loopback", "socat -b 65536", "WSS, default settings", "WSS, wss.socketBuffer=0 (OS sizes buffers)",
                "socat -b 2048", "WSS, wss.chunkSize=2048"};
            double[][] results = new double[names.length][runs];
            for (int run = 0; run < runs; run++) {
                results[0][run] = iperfDirect();
                results[1][run] = iperfThroughSocat(65536);
                results[2][run] = iperfThroughWss(wss);
                results[3][run] = iperfThroughWss(osBuffers);
                results[4][run] = iperfThroughSocat(2048);
                results[5][run] = iperfThroughWss(wss2k);
            }
            double direct = median(results[0]);
            System.out.println("| path | MB/s (median) | runs | vs socat (same chunk) | vs direct |");
            System.out.println("|---|---|---|---|---|");
            for (int i = 0; i < names.length; i++) {
                double m = median(results[i]);
                String vsSocat = i == 0 ? "" : String.format(Locale.ROOT, "%.2fx", m / median(results[i < 4 ? 1 : 4]));
                System.out.printf(Locale.ROOT, "| %s | %.0f | %s | %s | %.2fx |%n", names[i], m, runs(results[i]), vsSocat, m / direct);
            }
        }
    }

    private double iperfDirect() throws Exception {
        return iperfDirect(1);
    }

    private double iperfDirect(int streams) throws Exception {
        IperfServer iperf = iperfServer();
        int port = iperf.port();
        Process server = iperf.process();
        try {
            return iperfClient(port, streams);
        } finally {
            stop(server);
        }
    }

    private double iperfThroughSocat(int buffer) throws Exception {
        return iperfThroughSocat(buffer, 1);
    }

    private double iperfThroughSocat(int buffer, int streams) throws Exception {
        IperfServer iperf = iperfServer();
        int port = iperf.port();
        Process server = iperf.process();
        int relay = freePort();
        Process socat = socat(buffer, relay, port);
        try {
            return iperfClient(relay, streams);
        } finally {
            stop(socat);
            stop(server);
        }
    }

    private double iperfThroughWss(WssProcess wss) throws Exception {
        return iperfThroughWss(wss, 1);
    }

    /** iperf3 with {@code streams} parallel connections through one WSS port: that many links at once. */
    private double iperfThroughWss(WssProcess wss, int streams) throws Exception {
        IperfServer iperf = iperfServer();
        int port = iperf.port();
        Process server = iperf.process();
        try (ControlClient sink = new ControlClient(wss.controlPort, "Sink", port);
                ControlClient source = new ControlClient(wss.controlPort, "Source", 1)) {
            return iperfClient(source.dns("Sink"), streams);
        } finally {
            stop(server);
        }
    }

    private record IperfServer(Process process, int port) {
    }

    /** An iperf3 server on a free port; another if the port was taken meanwhile (its iperf3 then exits). */
    private IperfServer iperfServer() throws Exception {
        for (int attempt = 1;; attempt++) {
            int port = freePort();
            Process server = child("iperf3", "-s", "-1", "-B", "127.0.0.1", "-p", Integer.toString(port));
            try {
                waitListening(port, server);
                return new IperfServer(server, port);
            } catch (IOException e) {
                System.err.printf("  iperf3 -s on port %d: %s%n", port, server.isAlive() ? "not listening after 10 s" : "exited " + server.exitValue());
                stop(server);
                if (attempt == 5) {
                    throw e;
                }
            }
        }
    }

    /** MB/s received, from iperf3's JSON. */
    private double iperfClient(int port) throws Exception {
        return iperfClient(port, 1);
    }

    /** MB/s received by all of {@code streams} parallel connections together, from iperf3's JSON. */
    private double iperfClient(int port, int streams) throws Exception {
        return iperfResult(iperfJson(port, streams), RECEIVED_BPS) / 8 / 1e6;
    }

    /** iperf3's JSON report of {@code streams} parallel connections to the port for {@code --seconds}. */
    private String iperfJson(int port, int streams) throws Exception {
        Process client = child("iperf3", "-c", "127.0.0.1", "-p", Integer.toString(port), "-t", Integer.toString(seconds), "-J",
                "-P", Integer.toString(streams));
        String json = new String(client.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        client.waitFor(seconds + 30L, TimeUnit.SECONDS);
        return json;
    }

    private static double iperfResult(String json, Pattern field) throws IOException {
        Matcher matcher = field.matcher(json);
        if (!matcher.find()) {
            throw new IOException("no iperf3 result: " + json);
        }
        return Double.parseDouble(matcher.group(1));
    }

    // ---- the event log: the same streams with wss.eventLog off and on ----

    /** How many pairs of runs each pair of servers makes before both are started again. */
    private static final int PAIRS_PER_SERVERS = 5;

    private void eventLog() throws Exception {
        Path logs = Files.createTempDirectory("wss-bench-event-log");
        System.out.printf("%n## The CSV event log: throughput with wss.eventLog=false and true (iperf3, %d s, %d pairs of runs, ABBA)%n%n",
                seconds, runs);
        System.out.println("load average before: " + loadAverage());
        try {
            eventLogPairs(logs);
        } finally {
            System.out.println("load average after: " + loadAverage());
            reportAndDelete(logs);
        }
    }

    /**
     * Pairs of runs, one through each server, alternating which goes first (off-on, on-off, ...),
     * so that a machine whose load drifts favours neither; both servers are started afresh every
     * {@link #PAIRS_PER_SERVERS} pairs, so that what one JVM happens to be (how it compiled the
     * forwarding loop, where its memory lies) favours neither either; the ratio on/off is taken per pair and
     * its median given with a 95 % interval ({@link PairedRatios}). Beside the throughput, the CPU
     * each server spent per GB forwarded (all its threads, from /proc), which other processes' load
     * moves less than the throughput, and the event log's writer thread's. Last, what the log would
     * cost when the CPU is what limits the streams (2 cores shared by the WSS and iperf3's client and
     * server, as on the development machine): its writer's CPU per GB as a share of all the CPU the
     * machine spends per GB without the log (the WSS's and iperf3's, which reports its own).
     */
    private void eventLogPairs(Path logs) throws Exception {
        int[] streamCounts = {1, 8};
        Measured[][] offRuns = new Measured[streamCounts.length][runs];
        Measured[][] onRuns = new Measured[streamCounts.length][runs];
        for (int first = 0; first < runs; first += PAIRS_PER_SERVERS) {
            try (WssProcess off = WssProcess.start("wss.eventLog=false");
                    WssProcess on = WssProcess.start("wss.eventLog=true", "wss.eventLogDir=" + logs)) {
                for (int streams : new int[] {8, 1}) { // unmeasured: both servers warm and compiled, as after a while of a real run
                    iperfThroughWss(off, streams);
                    iperfThroughWss(on, streams);
                }
                for (int s = 0; s < streamCounts.length; s++) {
                    for (int run = first; run < Math.min(runs, first + PAIRS_PER_SERVERS); run++) {
                        if (run % 2 == 0) {
                            offRuns[s][run] = measuredThroughWss(off, streamCounts[s]);
                            onRuns[s][run] = measuredThroughWss(on, streamCounts[s]);
                        } else {
                            onRuns[s][run] = measuredThroughWss(on, streamCounts[s]);
                            offRuns[s][run] = measuredThroughWss(off, streamCounts[s]);
                        }
                    }
                }
            }
        }
        System.out.println("| links at once | log off MB/s (median) | log on MB/s (median) | on/off per pair | on/off: median of the pairs |");
        System.out.println("|---|---|---|---|---|");
        for (int s = 0; s < streamCounts.length; s++) {
            double[] ratios = new double[runs];
            for (int run = 0; run < runs; run++) {
                ratios[run] = onRuns[s][run].mbPerSecond / offRuns[s][run].mbPerSecond;
            }
            System.out.printf(Locale.ROOT, "| %d | %.0f | %.0f | %s | **%s** |%n", streamCounts[s], median(Measured.mbPerSecond(offRuns[s])),
                    median(Measured.mbPerSecond(onRuns[s])), ratios(ratios), new PairedRatios(ratios).summary());
        }
        System.out.println();
        System.out.println("| links at once | log off: the WSS's CPU s per GB (median) | log on | on/off per pair: median "
                + "| the log's writer thread, CPU s per GB | log off: the WSS's and iperf3's CPU s per GB "
                + "| on/off if the CPU is the limit: 1 - writer / all |");
        System.out.println("|---|---|---|---|---|---|---|");
        for (int s = 0; s < streamCounts.length; s++) {
            double[] cpuRatios = new double[runs];
            for (int run = 0; run < runs; run++) {
                cpuRatios[run] = onRuns[s][run].cpuPerGb() / offRuns[s][run].cpuPerGb();
            }
            double writerPerGb = median(Measured.writerPerGb(onRuns[s]));
            double allPerGb = median(Measured.allCpuPerGb(offRuns[s]));
            System.out.printf(Locale.ROOT, "| %d | %.3f | %.3f | %s | %.3f | %.2f | %.3f |%n", streamCounts[s],
                    median(Measured.cpuPerGb(offRuns[s])), median(Measured.cpuPerGb(onRuns[s])), new PairedRatios(cpuRatios).summary(),
                    writerPerGb, allPerGb, 1 - writerPerGb / allPerGb);
        }
    }

    /**
     * One run through a server: MB/s, GB forwarded, and the CPU seconds the server, its event log's
     * writer thread, and iperf3's client and server together spent in it.
     */
    private record Measured(double mbPerSecond, double gigabytes, double cpuSeconds, double writerSeconds, double iperfSeconds) {

        double cpuPerGb() {
            return cpuSeconds / gigabytes;
        }

        /** The machine's work per GB for this path: the WSS's CPU and iperf3's. */
        double allCpuPerGb() {
            return (cpuSeconds + iperfSeconds) / gigabytes;
        }

        static double[] allCpuPerGb(Measured[] runs) {
            return Arrays.stream(runs).mapToDouble(Measured::allCpuPerGb).toArray();
        }

        static double[] mbPerSecond(Measured[] runs) {
            return Arrays.stream(runs).mapToDouble(Measured::mbPerSecond).toArray();
        }

        static double[] cpuPerGb(Measured[] runs) {
            return Arrays.stream(runs).mapToDouble(Measured::cpuPerGb).toArray();
        }

        static double[] writerPerGb(Measured[] runs) {
            return Arrays.stream(runs).mapToDouble(run -> run.writerSeconds / run.gigabytes).toArray();
        }
    }

    /** As {@link #iperfThroughWss(WssProcess, int)}, with the server's CPU read from /proc just before and after the stream. */
    private Measured measuredThroughWss(WssProcess wss, int streams) throws Exception {
        IperfServer iperf = iperfServer();
        Process server = iperf.process();
        try (ControlClient sink = new ControlClient(wss.controlPort, "Sink", iperf.port());
                ControlClient source = new ControlClient(wss.controlPort, "Source", 1)) {
            int port = source.dns("Sink");
            long cpu = ProcessStats.cpuNanos(wss.pid());
            long writer = ProcessStats.threadCpuNanos(wss.pid(), "wss-event-log");
            String json = iperfJson(port, streams);
            double wssSeconds = (ProcessStats.cpuNanos(wss.pid()) - cpu) / 1e9;
            double writerSeconds = (ProcessStats.threadCpuNanos(wss.pid(), "wss-event-log") - writer) / 1e9;
            double mbPerSecond = iperfResult(json, RECEIVED_BPS) / 8 / 1e6;
            double iperfSeconds = (iperfResult(json, CLIENT_CPU) + iperfResult(json, SERVER_CPU)) / 100 * seconds;
            return new Measured(mbPerSecond, mbPerSecond * seconds / 1000, wssSeconds, writerSeconds, iperfSeconds);
        } finally {
            stop(server);
        }
    }

    /** The machine's load average over 1, 5 and 15 minutes, as /proc/loadavg says. */
    private static String loadAverage() throws IOException {
        String[] fields = Files.readString(Path.of("/proc/loadavg")).split(" ");
        return fields[0] + ", " + fields[1] + ", " + fields[2];
    }

    // ---- recording: the same streams with wss.record off and on ----

    /**
     * The stream through a WSS whose DistanceOnly model polls a world server of 12 robots 5 times a
     * second, all 12 registered (so every poll writes 12 robot and 66 pair rows), with
     * {@code wss.record} off and on, alternating which goes first (issue 17, docs/performance.md).
     */
    private void recording() throws Exception {
        Path dir = Files.createTempDirectory("wss-bench-record");
        Path world = dir.resolve("twelve.world");
        List<String> lines = new ArrayList<>(List.of("robot Sink 0,0,0", "robot Source 1,0,0"));
        for (int i = 1; i <= 10; i++) {
            lines.add("robot Idle" + i + " " + (i * 3) + ",5,0");
            lines.add("path Idle" + i + " speed 1 loop " + (i * 3) + ",25");
        }
        Files.write(dir.resolve("twelve.world"), lines);
        Path file = dir.resolve("run.rec");
        System.out.printf("%n## Recording: throughput with wss.record off and on (DistanceOnly polling 12 robots every 200 ms;"
                + " iperf3, %d s, %d pairs, alternating which goes first)%n%n", seconds, runs);
        try (org.usarsim.wss.world.WorldServer simulator = org.usarsim.wss.world.WorldServer.start(world,
                java.net.InetAddress.getLoopbackAddress(), 0)) {
            String[] model = {"wss.model=DistanceOnlyPropagationModel", "usarsim.port=" + simulator.port(), "usarsim.interval=200",
                "distance.cutoff=-200"};
            try (WssProcess off = WssProcess.start(model);
                    WssProcess on = WssProcess.start(concat(model, "wss.record=" + file));
                    Idle offIdle = new Idle(off.controlPort);
                    Idle onIdle = new Idle(on.controlPort)) {
                iperfThroughWss(off, 1); // unmeasured: both servers warm
                iperfThroughWss(on, 1);
                System.out.println("| links at once | record off MB/s (median) | record on MB/s (median) | on/off per pair | on/off (median of the pairs) |");
                System.out.println("|---|---|---|---|---|");
                double[] offRuns = new double[runs];
                double[] onRuns = new double[runs];
                double[] ratios = new double[runs];
                for (int run = 0; run < runs; run++) {
                    if (run % 2 == 0) {
                        offRuns[run] = iperfThroughWss(off, 1);
                        onRuns[run] = iperfThroughWss(on, 1);
                    } else {
                        onRuns[run] = iperfThroughWss(on, 1);
                        offRuns[run] = iperfThroughWss(off, 1);
                    }
                    ratios[run] = onRuns[run] / offRuns[run];
                }
                System.out.printf(Locale.ROOT, "| 1 | %.0f | %.0f | %s | **%.2fx** |%n", median(offRuns), median(onRuns), ratios(ratios),
                        median(ratios));
            }
            System.out.printf(Locale.ROOT, "%n  the recording: %,d bytes%n", Files.size(file));
        } finally {
            try (var files = Files.list(dir)) {
                for (Path path : files.toList()) {
                    Files.delete(path);
                }
            }
            Files.delete(dir);
        }
    }

    private static String[] concat(String[] some, String more) {
        String[] all = java.util.Arrays.copyOf(some, some.length + 1);
        all[some.length] = more;
        return all;
    }

    /** The ten idle robots of the recording's world, registered while the streams run. */
    private static final class Idle implements AutoCloseable {
        private final List<ControlClient> robots = new ArrayList<>();

        Idle(int controlPort) throws IOException {
            for (int i = 1; i <= 10; i++) {
                robots.add(new ControlClient(controlPort, "Idle" + i, 1));
            }
        }

        @Override
        public void close() throws IOException {
            for (ControlClient robot : robots) {
                robot.close();
            }
        }
    }

    // ---- per-link counting: this build beside one from before it, with socat and direct in the same runs ----

    /**
     * One stream and 8 streams through one WSS port, each run through direct loopback, socat and
     * this build, and (with {@code baseline}) a build from before a change (the per-link statistics,
     * the one forwarding loop), the two builds alternating which goes first; the ratio this/before
     * is taken per run, of the throughput and of the server's CPU per GB (which a loaded machine
     * moves less than the throughput).
     */
    private void counting(String baseline) throws Exception {
        System.out.printf("%n## Per-link counting: throughput against %s (iperf3, %d s, %d runs; load average %s)%n%n",
                baseline == null ? "socat and direct" : "the build before it (" + baseline + "), socat and direct", seconds, runs,
                loadAverage());
        try (WssProcess now = WssProcess.start(); WssProcess before = baseline == null ? null : WssProcess.startFrom(baseline)) {
            iperfThroughWss(now, 8); // unmeasured: both servers warm
            if (before != null) {
                iperfThroughWss(before, 8);
            }
            System.out.println("| links at once | direct MB/s | socat -b 65536 MB/s | WSS before MB/s | WSS now MB/s "
                    + "| now/before per run | now/before (median) | server CPU s per GB, before / now (median) "
                    + "| CPU per GB now/before (median) | now vs socat | now vs direct |");
            System.out.println("|---|---|---|---|---|---|---|---|---|---|---|");
            for (int streams : new int[] {1, 8}) {
                double[] direct = new double[runs];
                double[] socat = new double[runs];
                Measured[] beforeRuns = new Measured[runs];
                Measured[] nowRuns = new Measured[runs];
                double[] ratios = new double[runs];
                double[] cpuRatios = new double[runs];
                for (int run = 0; run < runs; run++) {
                    direct[run] = iperfDirect(streams);
                    socat[run] = iperfThroughSocat(65536, streams);
                    if (before != null && run % 2 == 1) {
                        beforeRuns[run] = measuredThroughWss(before, streams);
                    }
                    nowRuns[run] = measuredThroughWss(now, streams);
                    if (before != null && run % 2 == 0) {
                        beforeRuns[run] = measuredThroughWss(before, streams);
                    }
                    ratios[run] = before == null ? Double.NaN : nowRuns[run].mbPerSecond() / beforeRuns[run].mbPerSecond();
                    cpuRatios[run] = before == null ? Double.NaN : nowRuns[run].cpuPerGb() / beforeRuns[run].cpuPerGb();
                }
                double nowMb = median(Measured.mbPerSecond(nowRuns));
                System.out.printf(Locale.ROOT, "| %d | %.0f | %.0f | %.0f | %.0f | %s | **%.2fx** | %.3f / %.3f | %.2fx | %.2fx | %.2fx |%n",
                        streams, median(direct), median(socat), before == null ? Double.NaN : median(Measured.mbPerSecond(beforeRuns)),
                        nowMb, ratios(ratios), median(ratios), before == null ? Double.NaN : median(Measured.cpuPerGb(beforeRuns)),
                        median(Measured.cpuPerGb(nowRuns)), median(cpuRatios), nowMb / median(socat), nowMb / median(direct));
            }
        }
        System.out.printf("%nLoad average after: %s%n", loadAverage());
    }

    private static String ratios(double[] ratios) {
        StringBuilder text = new StringBuilder();
        for (double ratio : ratios) {
            text.append(text.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.2f", ratio));
        }
        return text.toString();
    }

    /** Counts the lines of the event logs and the events they say were dropped, and deletes them. */
    private static void reportAndDelete(Path logs) throws IOException {
        long written = 0;
        long dropped = 0;
        try (var files = Files.list(logs)) {
            for (Path file : files.toList()) {
                for (String line : Files.readAllLines(file)) {
                    if (line.startsWith("DROPPED,")) {
                        dropped += Long.parseLong(line.substring(line.lastIndexOf(',') + 1));
                    } else {
                        written++;
                    }
                }
                Files.delete(file);
            }
        }
        Files.delete(logs);
        System.out.printf(Locale.ROOT, "%nEvent log of the runs with the log on: %d lines written, %d events dropped (%.1f %%).%n",
                written, dropped, 100.0 * dropped / Math.max(1, written + dropped));
    }

    // ---- latency: 64-byte round trips ----

    private void latency() throws Exception {
        int rounds = 20_000;
        System.out.printf("%n## Round trip of a 64-byte message (%d rounds per run, best median of %d runs)%n%n", rounds, runs);
        try (EchoServer echo = new EchoServer(64); WssProcess wss = WssProcess.start();
                ControlClient echoRobot = new ControlClient(wss.controlPort, "Echo", echo.port());
                ControlClient client = new ControlClient(wss.controlPort, "Client", 1)) {
            int relay = freePort();
            Process socat = socat(65536, relay, echo.port());
            int wssPort = client.dns("Echo");
            String[] names = {"direct loopback", "socat -b 65536", "WSS"};
            int[] ports = {echo.port(), relay, wssPort};
            long[][] best = new long[names.length][];
            for (int run = 0; run < runs; run++) {
                for (int i = 0; i < names.length; i++) {
                    long[] rtts = roundTrips(ports[i], rounds, false, 2000);
                    if (best[i] == null || percentile(rtts, 50) < percentile(best[i], 50)) {
                        best[i] = rtts;
                    }
                }
            }
            stop(socat);
            double directMedian = percentile(best[0], 50) / 1e3;
            System.out.println("| path | median µs | p99 µs | added to direct (median) | added vs socat's |");
            System.out.println("|---|---|---|---|---|");
            double socatAdded = percentile(best[1], 50) / 1e3 - directMedian;
            for (int i = 0; i < names.length; i++) {
                double median = percentile(best[i], 50) / 1e3;
                double added = median - directMedian;
                System.out.printf(Locale.ROOT, "| %s | %.1f | %.1f | %s | %s |%n", names[i], median, percentile(best[i], 99) / 1e3,
                        i == 0 ? "" : String.format(Locale.ROOT, "%.1f µs", added),
                        i == 2 ? String.format(Locale.ROOT, "%.2fx", added / socatAdded) : "");
            }
        }
    }

    /**
     * Round-trip times in ns of {@code rounds} 64-byte messages, after {@code warmUp} unmeasured ones
     * on the same connection (a server that has run a while is warm); split: written as 16 + 48 bytes.
     * ShapingBenchmark's round trips too (a shaped link's delay: the generous timeout).
     */
    static long[] roundTrips(int port, int rounds, boolean split, int warmUp) throws IOException {
        try (Socket socket = new Socket()) {
            socket.setTcpNoDelay(true);
            socket.connect(new InetSocketAddress("127.0.0.1", port), 5000);
            socket.setSoTimeout(20_000);
            OutputStream out = socket.getOutputStream();
            InputStream in = socket.getInputStream();
            byte[] message = new byte[64];
            byte[] reply = new byte[64];
            long[] rtts = new long[rounds];
            for (int i = -warmUp; i < rounds; i++) {
                message[0] = (byte) i;
                long start = System.nanoTime();
                if (split) {
                    out.write(message, 0, 16);
                    out.write(message, 16, 48);
                } else {
                    out.write(message);
                }
                if (in.readNBytes(reply, 0, 64) != 64 || reply[0] != message[0]) {
                    throw new IOException("lost or wrong echo on port " + port);
                }
                if (i >= 0) {
                    rtts[i] = System.nanoTime() - start;
                }
            }
            return rtts;
        }
    }

    // ---- split writes: 16 + 48 bytes ----

    private void splitWrites() throws Exception {
        int rounds = 300;
        System.out.printf("%n## A 64-byte message written as 16 + 48 bytes and echoed (%d rounds after 5000 unmeasured)%n%n", rounds);
        try (EchoServer echo = new EchoServer(64); WssProcess wss = WssProcess.start();
                ControlClient echoRobot = new ControlClient(wss.controlPort, "Echo", echo.port());
                ControlClient client = new ControlClient(wss.controlPort, "Client", 1)) {
            int relay = freePort();
            Process socat = socat(65536, relay, echo.port());
            String[] names = {"direct loopback", "socat -b 65536", "WSS"};
            int[] ports = {echo.port(), relay, client.dns("Echo")};
            System.out.println("| path | median µs | p99 µs | worst ms | rounds over 5 ms |");
            System.out.println("|---|---|---|---|---|");
            for (int i = 0; i < names.length; i++) {
                long[] rtts = roundTrips(ports[i], rounds, true, 5000);
                long over = Arrays.stream(rtts).filter(t -> t > 5_000_000).count();
                System.out.printf(Locale.ROOT, "| %s | %.1f | %.1f | %.2f | %d |%n", names[i], percentile(rtts, 50) / 1e3,
                        percentile(rtts, 99) / 1e3, Arrays.stream(rtts).max().getAsLong() / 1e6, over);
            }
            stop(socat);
        }
    }

    // ---- many: 100 robots, 10 connections each ----

    private void manyConnections() throws Exception {
        int robots = 100;
        int peers = 10;
        int messageSize = 1024;
        System.out.printf("%n## %d robots, each with connections to %d others (%d forwarded connections), %d-byte echoes for %d s%n%n",
                robots, peers, robots * peers, messageSize, seconds);
        List<EchoServer> echoes = new ArrayList<>();
        for (int i = 0; i < robots; i++) {
            echoes.add(new EchoServer(messageSize));
        }
        try (WssProcess wss = WssProcess.start()) {
            ProcessStats atStart = ProcessStats.of(wss.pid());
            List<ControlClient> controls = new ArrayList<>();
            int[][] targets = new int[robots * peers][];
            for (int i = 0; i < robots; i++) {
                controls.add(new ControlClient(wss.controlPort, "R" + i, echoes.get(i).port()));
            }
            int[] wssPorts = new int[robots * peers];
            int[] directPorts = new int[robots * peers];
            for (int i = 0; i < robots; i++) {
                for (int k = 1; k <= peers; k++) {
                    int target = (i + k) % robots;
                    wssPorts[i * peers + k - 1] = controls.get(i).dns("R" + target);
                    directPorts[i * peers + k - 1] = echoes.get(target).port();
                }
            }
            ProcessStats registered = ProcessStats.of(wss.pid());
            Load direct = load(directPorts, messageSize, null);
            Load relayed = load(wssPorts, messageSize, wss);
            ProcessStats after = awaitSettled(wss.pid(), registered);
            for (ControlClient control : controls) {
                control.close();
            }
            ProcessStats deregistered = awaitSettled(wss.pid(), atStart);
            System.out.println("| path | connections | errors | MB/s (both ways) | p99 round trip ms | vs direct |");
            System.out.println("|---|---|---|---|---|---|");
            System.out.printf(Locale.ROOT, "| direct loopback | %d | %d | %.1f | %.2f | |%n", directPorts.length, direct.errors, direct.mbPerSecond(), direct.p99Ms());
            System.out.printf(Locale.ROOT, "| WSS | %d | %d | %.1f | %.2f | %.2fx throughput, %.2fx p99 |%n", wssPorts.length, relayed.errors,
                    relayed.mbPerSecond(), relayed.p99Ms(), relayed.mbPerSecond() / direct.mbPerSecond(), relayed.p99Ms() / direct.p99Ms());
            System.out.println();
            System.out.println("| WSS process | server threads | all threads | descriptors | resident MiB |");
            System.out.println("|---|---|---|---|---|");
            row("at start", atStart);
            row("100 robots registered, 1000 WSS ports listening", registered);
            row("during the run (1000 links)", relayed.during);
            row("after every connection closed", after);
            row("after every robot left", deregistered);
            System.out.println();
            System.out.println("Bytes lost or changed: " + (relayed.errors == 0 ? "none" : relayed.errors + " connections failed")
                    + "; every echo is checked byte for byte.");
        } finally {
            for (EchoServer echo : echoes) {
                echo.close();
            }
        }
    }

    private static void row(String when, ProcessStats stats) {
        System.out.printf(Locale.ROOT, "| %s | %d | %d | %d | %d |%n", when, stats.serverThreads(), stats.threads(), stats.descriptors(),
                stats.residentKiB() / 1024);
    }

    /** Waits (with a deadline) until the server's own threads are back to the reference's count, then reads its stats. */
    private static ProcessStats awaitSettled(long pid, ProcessStats reference) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        ProcessStats stats = ProcessStats.of(pid);
        while (stats.serverThreads() > reference.serverThreads() && System.nanoTime() < deadline) {
            Thread.sleep(50);
            stats = ProcessStats.of(pid);
        }
        return stats;
    }

    private record Load(long bytes, double seconds, long[] rtts, int errors, ProcessStats during) {
        double mbPerSecond() {
            return bytes / seconds / 1e6;
        }

        double p99Ms() {
            return percentile(rtts, 99) / 1e6;
        }
    }

    /** One thread per connection, each echoing messages for the run's seconds; all at once. */
    private Load load(int[] ports, int messageSize, WssProcess wss) throws Exception {
        int n = ports.length;
        Socket[] sockets = new Socket[n];
        for (int i = 0; i < n; i++) {
            sockets[i] = new Socket();
            sockets[i].setTcpNoDelay(true);
            sockets[i].connect(new InetSocketAddress("127.0.0.1", ports[i]), 10_000);
            sockets[i].setSoTimeout(20_000);
        }
        AtomicLong bytes = new AtomicLong();
        long[][] rtts = new long[n][];
        int[] errors = new int[1];
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        List<Thread> threads = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            int index = i;
            Thread thread = new Thread(null, () -> {
                long[] times = new long[1 << 16];
                int count = 0;
                byte[] message = new byte[messageSize];
                byte[] reply = new byte[messageSize];
                try {
                    OutputStream out = sockets[index].getOutputStream();
                    InputStream in = sockets[index].getInputStream();
                    for (long seq = 0; System.nanoTime() < end; seq++) {
                        Arrays.fill(message, (byte) (seq * 31 + index));
                        long start = System.nanoTime();
                        out.write(message);
                        if (in.readNBytes(reply, 0, messageSize) != messageSize || !Arrays.equals(message, reply)) {
                            throw new IOException("lost or changed bytes");
                        }
                        if (count < times.length) {
                            times[count++] = System.nanoTime() - start;
                        }
                        bytes.addAndGet(2L * messageSize);
                    }
                } catch (IOException e) {
                    synchronized (errors) {
                        errors[0]++;
                    }
                }
                rtts[index] = Arrays.copyOf(times, count);
            }, "load " + i, 256 * 1024);
            threads.add(thread);
        }
        long start = System.nanoTime();
        threads.forEach(Thread::start);
        ProcessStats during = null;
        if (wss != null) {
            Thread.sleep(TimeUnit.SECONDS.toMillis(seconds) / 2);
            during = ProcessStats.of(wss.pid());
        }
        for (Thread thread : threads) {
            thread.join();
        }
        double elapsed = (System.nanoTime() - start) / 1e9;
        for (Socket socket : sockets) {
            socket.close();
        }
        long[] all = Arrays.stream(rtts).flatMapToLong(Arrays::stream).toArray();
        return new Load(bytes.get(), elapsed, all, errors[0], during);
    }

    // ---- processes and helpers ----

    private Process socat(int buffer, int listenPort, int targetPort) throws Exception {
        Process socat = child("socat", "-b", Integer.toString(buffer),
                "TCP-LISTEN:" + listenPort + ",bind=127.0.0.1,reuseaddr,fork", "TCP:127.0.0.1:" + targetPort);
        waitListening(listenPort, socat);
        return socat;
    }

    /** Starts a helper program; only an iperf3 client's output is read, the rest is dropped (socat reports every connection iperf3 ends as an error). */
    private Process child(String... command) throws IOException {
        boolean readOutput = command[0].equals("iperf3") && command[1].equals("-c");
        ProcessBuilder builder = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.DISCARD);
        if (!readOutput) {
            builder.redirectOutput(ProcessBuilder.Redirect.DISCARD);
        }
        Process process = builder.start();
        children.add(process);
        return process;
    }

    private void stop(Process process) throws InterruptedException {
        process.destroy();
        if (!process.waitFor(5, TimeUnit.SECONDS)) {
            process.destroyForcibly();
        }
        children.remove(process);
    }

    private void killChildren() {
        for (Process process : new ArrayList<>(children)) {
            process.destroyForcibly();
        }
    }

    /** A port nothing uses, not even a connection in TIME_WAIT (Java binds over those, iperf3 and socat may not). */
    private static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket()) {
            socket.setReuseAddress(false);
            socket.bind(new InetSocketAddress("127.0.0.1", 0), 1);
            return socket.getLocalPort();
        }
    }

    /** Waits until something listens on 127.0.0.1:port, reading /proc/net/tcp (a probe connection would disturb iperf3). */
    private static void waitListening(int port, Process process) throws Exception {
        String local = String.format("0100007F:%04X", port);
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (System.nanoTime() < deadline && process.isAlive()) {
            for (String line : Files.readAllLines(Path.of("/proc/net/tcp"))) {
                String[] fields = line.trim().split("\\s+");
                if (fields.length > 3 && fields[1].equals(local) && fields[3].equals("0A")) {
                    return;
                }
            }
            Thread.sleep(10);
        }
        throw new IOException("nothing listens on port " + port);
    }

    static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }

    static double percentile(long[] values, double p) {
        long[] sorted = values.clone();
        Arrays.sort(sorted);
        int index = (int) Math.min(sorted.length - 1, Math.max(0, Math.ceil(p / 100.0 * sorted.length) - 1));
        return sorted[index];
    }

    private static String runs(double[] values) {
        StringBuilder text = new StringBuilder();
        for (double value : values) {
            text.append(text.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.0f", value));
        }
        return text.toString();
    }
}
