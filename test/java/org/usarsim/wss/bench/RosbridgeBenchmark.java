package org.usarsim.wss.bench;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Positions over rosbridge (issues 23 and 31, docs/performance.md "Positions over rosbridge"), the
 * WSS a headless process of its own with the DistanceOnly model, beside its USARSim path in the same
 * run.
 *
 * <p>{@code latency}: A stands at the origin, B jumps between 10 m and 100 m from it (range 55.6 m
 * with {@code distance.n = 3}) at random moments of the poll, {@code --changes} times; from the
 * publish of B's new place to the new strength on A's GETSS (asked every millisecond), and to the
 * pair's break or resume in the WSS's FINE log; at 5 Hz with a 200 ms poll and at 20 Hz with a
 * 100 ms poll (the fastest), each source against a WSS of its own ({@link LatencyRun}):
 * <ul>
 * <li>the USARSim socket ({@link UsarsimFeed}): publish is the moment B's place changes;</li>
 * <li>the world server's rosbridge side ({@link WorldFeed}; {@code --no-world} leaves it out): B
 * jumps by its world file, and publish is when a subscriber of the benchmark's own, with no
 * throttle and no queue, first sees the new place; the world server publishes at its tick (50 Hz)
 * at either poll;</li>
 * <li>a real rosbridge ({@code --real URL}, {@link RealRosbridgeFeed}): a real ROS node publishing
 * {@code gazebo_msgs/ModelStates} at 5 or 20 Hz on {@code --topic}, started by the benchmark as
 * {@code bash -c "PUBLISHER --mode place --rate HZ --topic TOPIC"}, {@code PUBLISHER} being
 * {@code --publisher} ({@code test/ros/latency_publisher.py} run with a ROS environment); publish
 * is the script's realtime clock just before its publish.</li>
 * </ul>
 * Printed: a line per source and rate with PASS or FAIL against issue 31's bounds (median at most
 * half a poll plus 20 ms, p99 at most a poll plus 50 ms), and the ratios of the medians and p99s to
 * the USARSim socket's. The WSS's own settings but the stale limit ({@code --stale}).
 *
 * <p>{@code cpu}: 100 robots moving ({@link Circles}), all registered, polled every 100 ms, the
 * WSS's CPU per second over {@code --seconds} after 3 s of warm-up ({@link CpuRun}): (i)
 * {@code /gazebo/model_states} at 20 Hz; (ii) 10 publishers on a tf topic ({@code --tf-topic}) at
 * 50 Hz each, 10 robots each; (iii) the USARSim socket. (i) and (ii) come from a rosbridge in this
 * JVM ({@link TinyPoseStream}), or with {@code --real} from the real one and
 * {@code latency_publisher.py --mode model_states} and {@code --mode tf}. The heap in use after a
 * full GC in (i), at the start and the end, and {@code --heap-samples} times more. The stale limit is
 * 1000 ms there unless {@code --stale} says otherwise, so that a loaded machine's pauses do not turn
 * into reconnections that the USARSim run does not pay.
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.RosbridgeBenchmark
 *     [--only latency|cpu] [--changes 40] [--seconds 60] [--robots 100] [--heap-samples 0]
 *     [--no-world] [--real ws://127.0.0.1:9090] [--publisher "python3 test/ros/latency_publisher.py"]
 *     [--topic /bench/model_states] [--tf-topic /bench/tf] [--stale MS]
 * </pre>
 */
public final class RosbridgeBenchmark {

    /** The publishing rate and the poll interval of each latency run. */
    private static final int[][] RATES = {{5, 200}, {20, 100}};

    private RosbridgeBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        Map<String, String> options = options(args);
        String only = options.getOrDefault("--only", "all");
        if (!only.equals("cpu")) {
            latency(options);
        }
        if (!only.equals("latency")) {
            cpu(options);
        }
        System.exit(0);
    }

    private static Map<String, String> options(String[] args) {
        Map<String, String> options = new LinkedHashMap<>();
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--no-world", "--world" -> options.put("--world", args[i].equals("--world") ? "on" : "off");
                case "--only", "--changes", "--seconds", "--robots", "--heap-samples", "--real", "--publisher", "--topic",
                        "--tf-topic", "--stale" -> {
                    if (i + 1 == args.length) {
                        throw new IllegalArgumentException(args[i] + " needs a value");
                    }
                    options.put(args[i], args[++i]);
                }
                default -> throw new IllegalArgumentException("unknown option " + args[i]);
            }
        }
        return options;
    }

    private static int number(Map<String, String> options, String name, int otherwise) {
        return options.containsKey(name) ? Integer.parseInt(options.get(name)) : otherwise;
    }

    private static String publisher(Map<String, String> options) {
        return options.getOrDefault("--publisher", "python3 test/ros/latency_publisher.py");
    }

    private static String topic(Map<String, String> options) {
        return options.getOrDefault("--topic", "/bench/model_states");
    }

    // ---- latency ----

    private static void latency(Map<String, String> options) throws Exception {
        int changes = number(options, "--changes", 40);
        String real = options.get("--real");
        List<String> stale = options.containsKey("--stale") ? List.of("rosbridge.stale=" + options.get("--stale")) : List.of();
        System.out.println("latency: B moved " + changes + " times between 10 m and 100 m from A (range 55.6 m)"
                + (stale.isEmpty() ? "" : ", " + stale.get(0)));
        for (int[] rate : RATES) {
            int hz = rate[0];
            int pollMs = rate[1];
            String at = String.format(Locale.ROOT, "%d Hz, poll %d ms", hz, pollMs);
            System.out.printf(Locale.ROOT, "%s: the bounds (issue 31) median <= %.0f ms, p99 <= %.0f ms%n", at,
                    Latencies.medianBound(pollMs), Latencies.p99Bound(pollMs));
            Latencies usarsim = run(at, "USARSim socket", () -> new UsarsimFeed(pollMs), pollMs, changes, stale);
            List<String> ratios = new ArrayList<>();
            if (!"off".equals(options.get("--world"))) {
                ratios.add(ratio("world", run(at, "world server", () -> new WorldFeed(hz, pollMs, changes), pollMs, changes, stale),
                        usarsim));
            }
            if (real != null) {
                ratios.add(ratio("rosbridge", run(at, "real rosbridge", () -> new RealRosbridgeFeed(real, publisher(options),
                        topic(options), hz, pollMs), pollMs, changes, stale), usarsim));
            }
            if (!ratios.isEmpty()) {
                System.out.println("  " + at + ", ratios: " + String.join("; ", ratios));
            }
        }
    }

    /** Opens a source of the latency run: it may fail to start. */
    private interface FeedStart {
        PositionFeed open() throws Exception;
    }

    /** One source at one rate, its line printed; null when it failed (said). */
    private static Latencies run(String at, String name, FeedStart start, int pollMs, int changes, List<String> more) {
        try (PositionFeed feed = start.open()) {
            Latencies latencies = LatencyRun.measure(feed, pollMs, changes, more);
            String said = feed.finish();
            System.out.println("  " + at + ", " + feed.label() + ": " + latencies.line(pollMs) + (said.isEmpty() ? "" : " (" + said
                    + ")"));
            return latencies;
        } catch (Exception e) {
            System.out.println("  " + at + ", " + name + ": FAILED, " + e);
            return null;
        }
    }

    private static String ratio(String name, Latencies source, Latencies usarsim) {
        if (source == null || usarsim == null) {
            return name + "/USARSim: -";
        }
        return String.format(Locale.ROOT, "%s/USARSim median %.2f, p99 %.2f", name, source.median() / usarsim.median(),
                source.p99() / usarsim.p99());
    }

    // ---- CPU and heap ----

    private static void cpu(Map<String, String> options) throws Exception {
        int robots = number(options, "--robots", 100);
        int seconds = number(options, "--seconds", 60);
        int heapSamples = number(options, "--heap-samples", 0);
        String real = options.get("--real");
        String tfTopic = options.getOrDefault("--tf-topic", "/bench/tf");
        List<String> stale = List.of("rosbridge.stale=" + options.getOrDefault("--stale", "1000"));
        String where = real == null ? "the rosbridge in this JVM" : "the real rosbridge at " + real;
        int publishers = 10;
        System.out.printf(Locale.ROOT, "cpu: %d robots moving, poll 100 ms, %d s each, %s, %s%n", robots, seconds, where,
                stale.get(0));
        CpuRun run = new CpuRun(robots, seconds);
        double states;
        try (PoseStream stream = real == null ? TinyPoseStream.modelStates(robots, 20)
                : RealPoseStream.modelStates(real, publisher(options), topic(options), robots, 20)) {
            states = run.rosbridge("model states", stream, stale, heapSamples);
        }
        double tf;
        try (PoseStream stream = real == null ? TinyPoseStream.tf(tfTopic, robots, publishers, 50)
                : RealPoseStream.tf(real, publisher(options), tfTopic, robots, publishers, 50)) {
            tf = run.rosbridge("tf", stream, stale, -1);
        }
        double usarsim = run.usarsim();
        System.out.println(CpuRun.line("(i) ModelStates of all at 20 Hz", states, usarsim));
        System.out.println(CpuRun.line("(ii) " + publishers + " tf publishers at 50 Hz, " + robots / publishers + " robots each",
                tf, usarsim));
        System.out.println(CpuRun.line("(iii) USARSim socket, GETPOS every 100 ms", usarsim, usarsim));
    }
}
