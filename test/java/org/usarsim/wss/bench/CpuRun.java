package org.usarsim.wss.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.function.LongFunction;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.usarsim.wss.model.simulator.FakeSimulator;
import org.usarsim.wss.model.simulator.ReportedRobot;

/**
 * The WSS's CPU with many robots moving ({@link Circles}), all registered, polled every 100 ms:
 * a headless WSS process (DistanceOnly) for each source, its CPU per second over a span (/proc), and
 * the heap in use after a full GC ({@code jcmd}).
 */
final class CpuRun {

    static final Pattern USED = Pattern.compile("used (\\d+)K");

    private final int robots;
    private final int seconds;

    CpuRun(int robots, int seconds) {
        this.robots = robots;
        this.seconds = seconds;
    }

    /**
     * A rosbridge source: the WSS's ms of CPU a second, once positions came and after 3 s of warm-up;
     * with {@code heapSamples} at 0 or more, the heap after a full GC at the start and end, and then
     * that many times more, every {@code seconds}.
     */
    double rosbridge(String name, PoseStream stream, List<String> more, int heapSamples) throws Exception {
        List<String> settings = new ArrayList<>(stream.wssSettings());
        settings.addAll(more);
        double cpu;
        long silences;
        try (WssProcess wss = start(settings)) {
            List<ControlClient> clients = register(wss);
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (wss.lineTime("positions from", 0) < 0 && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            Thread.sleep(3_000); // warm up: the first polls, the JIT
            long heapStart = heapSamples >= 0 ? heapAfterGc(wss.pid()) : -1;
            cpu = cpuPerSecond(wss);
            if (heapSamples >= 0) {
                System.out.println("  heap in use after a full GC, " + name + ": " + heapStart + " KiB at the start, "
                        + heapAfterGc(wss.pid()) + " KiB after " + seconds + " s");
            }
            for (int i = 1; i <= heapSamples; i++) {
                Thread.sleep(TimeUnit.SECONDS.toMillis(seconds));
                System.out.println("  heap in use after a full GC, " + name + ", " + (i + 1) * seconds + " s: " + heapAfterGc(wss.pid())
                        + " KiB");
            }
            silences = wss.linesContaining("lost the simulator");
            close(clients);
        }
        // The WSS first: it would say the silence of publishers that stopped.
        System.out.println("  " + name + ": " + stream.finish() + "; " + silences + " silences said");
        return cpu;
    }

    /** The peer: the same robots in a USARSim position socket ({@link FakeSimulator}), GETPOS every 100 ms. */
    double usarsim() throws Exception {
        try (FakeSimulator fake = new FakeSimulator()) {
            long start = System.nanoTime();
            LongFunction<List<ReportedRobot>> script = k -> {
                double t = (System.nanoTime() - start) / 1e9;
                List<ReportedRobot> list = new ArrayList<>();
                for (int i = 0; i < robots; i++) {
                    double[] p = Circles.at(i, t);
                    list.add(new ReportedRobot("R" + i, p[0], p[1], 0, false));
                }
                return list;
            };
            fake.script(script);
            try (WssProcess wss = start(List.of("positions=usarsim", "usarsim.host=127.0.0.1", "usarsim.port=" + fake.port()))) {
                List<ControlClient> clients = register(wss);
                Thread.sleep(3_000);
                double cpu = cpuPerSecond(wss);
                close(clients);
                return cpu;
            }
        }
    }

    private static WssProcess start(List<String> source) throws IOException, InterruptedException {
        List<String> settings = new ArrayList<>(List.of("wss.model=DistanceOnlyPropagationModel", "positions.interval=100",
                "distance.n=3"));
        settings.addAll(source);
        return WssProcess.start(settings.toArray(String[]::new));
    }

    private List<ControlClient> register(WssProcess wss) throws IOException {
        List<ControlClient> clients = new ArrayList<>();
        for (int i = 0; i < robots; i++) {
            clients.add(new ControlClient(wss.controlPort, "R" + i, 41000 + i));
        }
        return clients;
    }

    private static void close(List<ControlClient> clients) throws IOException {
        for (ControlClient client : clients) {
            client.close();
        }
    }

    /** The process's CPU in milliseconds per second over {@link #seconds}. */
    private double cpuPerSecond(WssProcess wss) throws IOException, InterruptedException {
        long cpu = ProcessStats.cpuNanos(wss.pid());
        long start = System.nanoTime();
        Thread.sleep(TimeUnit.SECONDS.toMillis(seconds));
        double used = (ProcessStats.cpuNanos(wss.pid()) - cpu) / 1e6;
        return used / ((System.nanoTime() - start) / 1e9);
    }

    /** The heap in use after a full GC, by jcmd, in KiB. */
    static long heapAfterGc(long pid) throws IOException, InterruptedException {
        run("jcmd", Long.toString(pid), "GC.run");
        Matcher matcher = USED.matcher(run("jcmd", Long.toString(pid), "GC.heap_info"));
        return matcher.find() ? Long.parseLong(matcher.group(1)) : -1;
    }

    static String run(String... command) throws IOException, InterruptedException {
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        String out = new String(process.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        process.waitFor();
        return out;
    }

    /** One line of the report: a source's CPU and its ratio to the peer's. */
    static String line(String source, double cpu, double usarsim) {
        return String.format(Locale.ROOT, "  %-58s %7.1f ms CPU/s, %.2fx USARSim", source, cpu, cpu / usarsim);
    }
}
