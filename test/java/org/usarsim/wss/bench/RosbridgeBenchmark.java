package org.usarsim.wss.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.function.LongFunction;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.usarsim.wss.model.simulator.FakeSimulator;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.model.simulator.TinyRosbridge;
import org.usarsim.wss.protocol.Replies;

/**
 * Positions over rosbridge (issue 23), the WSS a headless process of its own with the DistanceOnly
 * model, {@code positions = rosbridge}, a rosbridge in this JVM ({@link TinyRosbridge}) publishing
 * {@code /gazebo/model_states}:
 * <ul>
 * <li>{@code latency}: robot B jumps between 10 m and 100 m from A (range 55.6 m); from the publish
 * of the first message with its new place to the new strength on A's GETSS, and to the pair's break
 * or resume in the WSS's log; at 5 Hz (poll 200 ms) and 20 Hz (poll 100 ms, the fastest);</li>
 * <li>{@code cpu}: 100 robots moving, published at 20 Hz, polled every 100 ms: the WSS's CPU per
 * second, beside the same robots from a USARSim position socket polled every 100 ms; the heap in use
 * after a full GC at the start and the end of the rosbridge run. The stale limit is 1000 ms there
 * ({@code -Dwss.bench.stale=300} for the default of 3 polls), so that a loaded machine's pauses do
 * not turn into reconnections that the USARSim run does not pay.</li>
 * </ul>
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.RosbridgeBenchmark [--only latency|cpu] [--changes 40] [--seconds 60]
 *     [--heap-samples 9]   (the rosbridge WSS's heap after a full GC every --seconds, this many more times)
 * </pre>
 */
public final class RosbridgeBenchmark {

    private static final PathLoss N3 = new PathLoss(-49.67, 3, 2, -93);

    private RosbridgeBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        String only = "all";
        int changes = 40;
        int seconds = 60;
        int robots = 100;
        int heapSamples = 0;
        for (int i = 0; i < args.length; i += 2) {
            switch (args[i]) {
                case "--only" -> only = args[i + 1];
                case "--changes" -> changes = Integer.parseInt(args[i + 1]);
                case "--seconds" -> seconds = Integer.parseInt(args[i + 1]);
                case "--robots" -> robots = Integer.parseInt(args[i + 1]);
                case "--heap-samples" -> heapSamples = Integer.parseInt(args[i + 1]);
                default -> throw new IllegalArgumentException("unknown option " + args[i]);
            }
        }
        if (!only.equals("cpu")) {
            latency(5, 200, changes);
            usarsimLatency(200, changes);
            latency(20, 100, changes);
            usarsimLatency(100, changes);
        }
        if (!only.equals("latency")) {
            cpu(robots, seconds, heapSamples);
        }
        System.exit(0);
    }

    // ---- latency ----

    private static void latency(int hz, int intervalMs, int changes) throws Exception {
        try (TinyRosbridge ros = new TinyRosbridge();
                WssProcess wss = WssProcess.start("wss.model=DistanceOnlyPropagationModel", "positions=rosbridge",
                        "rosbridge.url=" + ros.url(), "positions.interval=" + intervalMs, "distance.n=3", "wss.logLevel=FINE")) {
            Publisher publisher = new Publisher(ros, hz);
            publisher.place("A", 0, 0);
            publisher.place("B", 10, 0);
            publisher.start();
            ControlClient a = new ControlClient(wss.controlPort, "A", 40001);
            new ControlClient(wss.controlPort, "B", 40002);
            awaitStrength(a, 10, System.nanoTime() + TimeUnit.SECONDS.toNanos(20));
            Random random = new Random(23);
            List<Double> getss = new ArrayList<>();
            List<Double> links = new ArrayList<>();
            double at = 10;
            for (int i = 0; i < changes; i++) {
                Thread.sleep(random.nextInt(intervalMs) + intervalMs);
                at = at == 10 ? 100 : 10;
                int lines = wss.lineCount();
                long published = publisher.moveAndAwaitPublish("B", at, 0);
                long strength = awaitStrength(a, at, published + TimeUnit.SECONDS.toNanos(10));
                String event = at == 100 ? "out of range: A - B" : "in range: A - B";
                long link;
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                while ((link = wss.lineTime(event, lines)) < 0 && System.nanoTime() < deadline) {
                    Thread.sleep(1);
                }
                getss.add((strength - published) / 1e6);
                links.add((link - published) / 1e6);
            }
            publisher.stop();
            System.out.printf(Locale.ROOT, "latency %d Hz (poll %d ms), %d changes: publish -> GETSS median %.1f ms, p99 %.1f ms;"
                    + " publish -> break/resume median %.1f ms, p99 %.1f ms%n", hz, intervalMs, changes, median(getss), p99(getss),
                    median(links), p99(links));
        }
    }

    /** The peer: the same jumps of B in a USARSim position socket (this JVM's), polled at the same interval. */
    private static void usarsimLatency(int intervalMs, int changes) throws Exception {
        try (FakeSimulator fake = new FakeSimulator()) {
            fake.place("A", 0, 0, 0);
            fake.place("B", 10, 0, 0);
            try (WssProcess wss = WssProcess.start("wss.model=DistanceOnlyPropagationModel", "positions=usarsim",
                    "usarsim.host=127.0.0.1", "usarsim.port=" + fake.port(), "positions.interval=" + intervalMs, "distance.n=3",
                    "wss.logLevel=FINE")) {
                ControlClient a = new ControlClient(wss.controlPort, "A", 40001);
                new ControlClient(wss.controlPort, "B", 40002);
                awaitStrength(a, 10, System.nanoTime() + TimeUnit.SECONDS.toNanos(20));
                Random random = new Random(23);
                List<Double> getss = new ArrayList<>();
                List<Double> links = new ArrayList<>();
                double at = 10;
                for (int i = 0; i < changes; i++) {
                    Thread.sleep(random.nextInt(intervalMs) + intervalMs);
                    at = at == 10 ? 100 : 10;
                    int lines = wss.lineCount();
                    long placed = System.nanoTime();
                    fake.place("B", at, 0, 0);
                    long strength = awaitStrength(a, at, placed + TimeUnit.SECONDS.toNanos(10));
                    String event = at == 100 ? "out of range: A - B" : "in range: A - B";
                    long link;
                    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                    while ((link = wss.lineTime(event, lines)) < 0 && System.nanoTime() < deadline) {
                        Thread.sleep(1);
                    }
                    getss.add((strength - placed) / 1e6);
                    links.add((link - placed) / 1e6);
                }
                System.out.printf(Locale.ROOT, "  peer, USARSim socket (poll %d ms), %d changes: move -> GETSS median %.1f ms, p99 %.1f ms;"
                        + " move -> break/resume median %.1f ms, p99 %.1f ms%n", intervalMs, changes, median(getss), p99(getss),
                        median(links), p99(links));
            }
        }
    }

    /** Asks A's GETSS for B every millisecond until it shows the strength at {@code metres}; when it did. */
    private static long awaitStrength(ControlClient a, double metres, long deadline) throws IOException, InterruptedException {
        String expected = Replies.signal("B", N3.strength(metres));
        while (System.nanoTime() < deadline) {
            if (a.ask("GETSS {Robot B}").equals(expected)) {
                return System.nanoTime();
            }
            Thread.sleep(1);
        }
        throw new IOException("GETSS never showed B at " + metres + " m");
    }

    /** Publishes model_states at its rate; says when the first message with a change went out. */
    private static final class Publisher {
        private final TinyRosbridge ros;
        private final long periodNs;
        private final Map<String, double[]> world = Collections.synchronizedMap(new LinkedHashMap<>());
        private volatile boolean running = true;
        private Thread thread;

        Publisher(TinyRosbridge ros, int hz) {
            this.ros = ros;
            this.periodNs = TimeUnit.SECONDS.toNanos(1) / hz;
        }

        void place(String name, double x, double y) {
            world.put(name, new double[] {x, y});
        }

        void start() {
            thread = new Thread(() -> {
                long next = System.nanoTime();
                while (running) {
                    synchronized (this) {
                        ros.publish(modelStatesNow());
                    }
                    next += periodNs;
                    long wait = next - System.nanoTime();
                    if (wait > 0) {
                        try {
                            TimeUnit.NANOSECONDS.sleep(wait);
                        } catch (InterruptedException e) {
                            return;
                        }
                    }
                }
            }, "publisher");
            thread.setDaemon(true);
            thread.start();
        }

        /**
         * Moves the robot and publishes at once, out of the tick, so that the change comes at a
         * random phase of the WSS's poll (the tick's phase against the poll's stays the same for a
         * whole run); when it went out.
         */
        synchronized long moveAndAwaitPublish(String name, double x, double y) {
            place(name, x, y);
            long now = System.nanoTime();
            ros.publish(modelStatesNow());
            return now;
        }

        private String modelStatesNow() {
            return TinyRosbridge.modelStates(new LinkedHashMap<>(world));
        }

        void stop() throws InterruptedException {
            running = false;
            thread.interrupt();
            thread.join(5_000);
        }
    }

    // ---- CPU and heap ----

    /** Robot i at time t (s): on a circle of 30 m around its own centre, so that some pairs go in and out of range. */
    private static double[] at(int i, double t) {
        double angle = t * 0.5 + i;
        return new double[] {(i % 10) * 20 + 30 * Math.cos(angle), (i / 10) * 20 + 30 * Math.sin(angle)};
    }

    private static void cpu(int robots, int seconds, int heapSamples) throws Exception {
        double rosbridge;
        long[] heap;
        try (TinyRosbridge ros = new TinyRosbridge();
                WssProcess wss = WssProcess.start("wss.model=DistanceOnlyPropagationModel", "positions=rosbridge",
                        "rosbridge.url=" + ros.url(), "positions.interval=100", "distance.n=3",
                        "rosbridge.stale=" + System.getProperty("wss.bench.stale", "1000"))) {
            long start = System.nanoTime();
            Publisher publisher = new Publisher(ros, 20);
            Thread mover = new Thread(() -> {
                while (!Thread.currentThread().isInterrupted()) {
                    double t = (System.nanoTime() - start) / 1e9;
                    synchronized (publisher) {
                        for (int i = 0; i < robots; i++) {
                            double[] p = at(i, t);
                            publisher.place("R" + i, p[0], p[1]);
                        }
                    }
                    try {
                        Thread.sleep(50);
                    } catch (InterruptedException e) {
                        return;
                    }
                }
            }, "mover");
            mover.setDaemon(true);
            for (int i = 0; i < robots; i++) {
                double[] p = at(i, 0);
                publisher.place("R" + i, p[0], p[1]);
            }
            mover.start();
            publisher.start();
            List<ControlClient> clients = register(wss, robots);
            long heapStart = heapAfterGc(wss.pid());
            rosbridge = cpuPerSecond(wss, seconds);
            long heapEnd = heapAfterGc(wss.pid());
            for (int i = 1; i <= heapSamples; i++) {
                Thread.sleep(TimeUnit.SECONDS.toMillis(seconds));
                System.out.println("  heap in use after a full GC, rosbridge, " + (i + 1) * seconds + " s: " + heapAfterGc(wss.pid()) + " KiB");
            }
            heap = new long[] {heapStart, heapEnd};
            System.out.println("  (" + wss.linesContaining("lost the simulator") + " silences of rosbridge said in the run)");
            mover.interrupt();
            publisher.stop();
            System.out.println("  (" + clients.size() + " robots registered over rosbridge)");
        }
        double usarsim;
        try (FakeSimulator fake = new FakeSimulator()) {
            long start = System.nanoTime();
            LongFunction<List<ReportedRobot>> script = k -> {
                double t = (System.nanoTime() - start) / 1e9;
                List<ReportedRobot> list = new ArrayList<>();
                for (int i = 0; i < robots; i++) {
                    double[] p = at(i, t);
                    list.add(new ReportedRobot("R" + i, p[0], p[1], 0, false));
                }
                return list;
            };
            fake.script(script);
            try (WssProcess wss = WssProcess.start("wss.model=DistanceOnlyPropagationModel", "positions=usarsim",
                    "usarsim.host=127.0.0.1", "usarsim.port=" + fake.port(), "positions.interval=100", "distance.n=3")) {
                register(wss, robots);
                System.out.println("  heap in use after a full GC, USARSim, start: " + heapAfterGc(wss.pid()) + " KiB");
                usarsim = cpuPerSecond(wss, seconds);
                System.out.println("  heap in use after a full GC, USARSim, " + seconds + " s: " + heapAfterGc(wss.pid()) + " KiB");
            }
        }
        System.out.printf(Locale.ROOT, "cpu %d robots, poll 100 ms, %d s each: rosbridge (model_states at 20 Hz) %.1f ms CPU/s,"
                + " USARSim socket (GETPOS at 10 Hz) %.1f ms CPU/s, ratio %.2f; heap in use after a full GC %d KiB at the start,"
                + " %d KiB after %d s%n", robots, seconds, rosbridge, usarsim, rosbridge / usarsim, heap[0], heap[1], seconds);
    }

    private static List<ControlClient> register(WssProcess wss, int robots) throws IOException, InterruptedException {
        List<ControlClient> clients = new ArrayList<>();
        for (int i = 0; i < robots; i++) {
            clients.add(new ControlClient(wss.controlPort, "R" + i, 41000 + i));
        }
        Thread.sleep(3_000); // warm up: the first polls, the JIT
        return clients;
    }

    /** The process's CPU in milliseconds per second over {@code seconds}. */
    private static double cpuPerSecond(WssProcess wss, int seconds) throws IOException, InterruptedException {
        long cpu = ProcessStats.cpuNanos(wss.pid());
        long start = System.nanoTime();
        Thread.sleep(TimeUnit.SECONDS.toMillis(seconds));
        double used = (ProcessStats.cpuNanos(wss.pid()) - cpu) / 1e6;
        return used / ((System.nanoTime() - start) / 1e9);
    }

    private static final Pattern USED = Pattern.compile("used (\\d+)K");

    /** The heap in use after a full GC, by jcmd, in KiB. */
    private static long heapAfterGc(long pid) throws IOException, InterruptedException {
        run("jcmd", Long.toString(pid), "GC.run");
        Matcher matcher = USED.matcher(run("jcmd", Long.toString(pid), "GC.heap_info"));
        return matcher.find() ? Long.parseLong(matcher.group(1)) : -1;
    }

    private static String run(String... command) throws IOException, InterruptedException {
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        String out = new String(process.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        process.waitFor();
        return out;
    }

    private static double median(List<Double> values) {
        List<Double> sorted = values.stream().sorted().toList();
        return sorted.get(sorted.size() / 2);
    }

    private static double p99(List<Double> values) {
        List<Double> sorted = values.stream().sorted().toList();
        return sorted.get(Math.min(sorted.size() - 1, (int) Math.ceil(sorted.size() * 0.99) - 1));
    }
}
