package org.usarsim.wss.bench;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.RouteGraphs;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.PollingStub;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.routes.RouteFinder;
import org.usarsim.wss.routes.RouteGraph;
import org.usarsim.wss.routes.RouteRule;
import org.usarsim.wss.monitor.RouteEventSizes;
import org.usarsim.wss.routes.RouteTable;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * Issue 34, measured (docs/routes.md, docs/performance.md): N robots (100) registered on a hub in
 * this JVM, links shaped, moving on {@link Circles} (the CPU run's motion) under a model that polls
 * every 200 ms as the simulator models do (each pair's strength by the path loss, every pair decided
 * in one go, the poll told): within range of each other, every pair is up, a full mesh whose rates
 * follow the distances. At every poll the benchmark takes what the hub's {@code wss-routes} thread
 * takes (a snapshot, the graph, every route; the hub's own thread runs too) and times it against the
 * poll interval (the table found lazily: the routes to the base, {@code wss.route.base = R0}), and apart every
 * route of every robot (the window's Routes table); every 10 s the heap after a GC; and the bytes of
 * the monitor's routes events a stream is told meanwhile ({@link RouteEventSizes}).
 *
 * <pre>
 * java -cp target/classes:target/test-classes:JUNIT_API:OPENTEST4J org.usarsim.wss.bench.RouteBenchmark [--robots 100] [--seconds 180]
 * </pre>
 */
public final class RouteBenchmark {

    private static final long POLL_MS = 200;
    /** -40 dBm at 1 m, exponent 2: 446 m to -93 dBm, more than the circles span; the rates step from 54 to 6 Mbit/s. */
    private static final PathLoss LOSS = new PathLoss(-40, 2.0, 1, -93);

    private RouteBenchmark() {
    }

    /** Robot i on its circle at this time; every pair's strength by the path loss, up within the cutoff. */
    private static void poll(PollingStub model, int robots, double seconds) {
        List<ModelPoll.Robot> listed = new ArrayList<>();
        double[][] at = new double[robots][];
        for (int i = 0; i < robots; i++) {
            at[i] = Circles.at(i, seconds);
            listed.add(new ModelPoll.Robot("R" + i, new Position(at[i][0], at[i][1], 0), false));
        }
        List<ModelPoll.Pair> pairs = new ArrayList<>();
        for (int i = 0; i < robots; i++) {
            for (int j = i + 1; j < robots; j++) {
                double dBm = LOSS.strength(Math.max(1, Math.hypot(at[i][0] - at[j][0], at[i][1] - at[j][1])));
                pairs.add(new ModelPoll.Pair("R" + i, "R" + j, dBm, 0, dBm >= LOSS.cutoff()));
            }
        }
        model.poll(listed, pairs);
    }

    public static void main(String[] args) throws Exception {
        int robots = 100;
        int seconds = 180;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--robots" -> robots = Integer.parseInt(args[++i]);
                case "--seconds" -> seconds = Integer.parseInt(args[++i]);
                default -> throw new IllegalArgumentException("unknown argument " + args[i]);
            }
        }
        ShapingConfig shaping = new ShapingConfig(true, RateTable.DEFAULT, ShapingConfig.DEFAULT_DELAY_MS, true);
        HubConfig config = TestHub.config(false, 65536, 600, 1000, 30).withShaping(shaping, Map.of());
        PollingStub model = new PollingStub();
        List<TestRobot> clients = new ArrayList<>();
        List<Long> whole = new ArrayList<>();
        List<Long> finding = new ArrayList<>();
        RouteEventSizes events = new RouteEventSizes();
        try (TestHub server = new TestHub(model, config)) {
            server.hub.setRouteBase("R0");
            for (int i = 0; i < robots; i++) {
                TestRobot robot = server.robot();
                clients.add(robot);
                robot.init("R" + i, 5000);
            }
            long start = System.nanoTime();
            long end = start + TimeUnit.SECONDS.toNanos(seconds);
            long nextHeap = start;
            int hops = 0;
            long pairsUp = 0;
            while (System.nanoTime() < end) {
                long pollAt = System.nanoTime();
                poll(model, robots, (pollAt - start) / 1e9);
                long t0 = System.nanoTime();
                HubSnapshot snapshot = server.hub.snapshot();
                RouteGraph graph = RouteGraphs.of(snapshot, RouteRule.of(shaping), "R0");
                long t1 = System.nanoTime();
                RouteTable table = RouteFinder.table(graph);
                table.cutOff(); // what the hub's thread computes at each change: the base's routes
                long t2 = System.nanoTime();
                table.all(); // every route, as the window's Routes table asks them
                long t3 = System.nanoTime();
                events.next(table, t3);
                whole.add(t2 - t0);
                finding.add(t3 - t2);
                pairsUp = graph.hops().size() / 2;
                hops = Math.max(hops, table.all().stream().mapToInt(route -> route.hops()).max().orElse(0));
                if (pollAt >= nextHeap) {
                    System.gc();
                    Runtime runtime = Runtime.getRuntime();
                    System.out.printf(Locale.ROOT, "t=%3.0f s heap used after GC %.1f MiB%n", (pollAt - start) / 1e9,
                            (runtime.totalMemory() - runtime.freeMemory()) / 1048576.0);
                    nextHeap = pollAt + TimeUnit.SECONDS.toNanos(10);
                }
                long sleep = POLL_MS - (System.nanoTime() - pollAt) / 1_000_000;
                if (sleep > 0) {
                    Thread.sleep(sleep);
                }
            }
            System.out.printf(Locale.ROOT, "%d robots, %d pairs up at the last poll, longest route %d hops, %d recomputations%n", robots,
                    pairsUp, hops, whole.size());
            System.out.println("a recomputation (snapshot, graph, routes to the base): " + stats(whole) + " (poll interval " + POLL_MS
                    + " ms)");
            System.out.println("every route besides (RouteTable.all, the Routes table's): " + stats(finding));
            System.out.printf(Locale.ROOT, "the monitor's stream: %d route events told, %.1f KB/s (the whole table at each of its %d changes:"
                    + " %.1f KB/s)%n", events.events(), events.told() / 1e3 / seconds, events.changes(), events.whole() / 1e3 / seconds);
        } finally {
            for (TestRobot robot : clients) {
                robot.close();
            }
        }
        System.exit(0);
    }

    private static String stats(List<Long> nanos) {
        long[] sorted = nanos.stream().mapToLong(Long::longValue).sorted().toArray();
        return String.format(Locale.ROOT, "median %.1f ms, p99 %.1f ms, max %.1f ms", sorted[sorted.length / 2] / 1e6,
                sorted[(int) Math.min(sorted.length - 1, Math.ceil(sorted.length * 0.99) - 1)] / 1e6, sorted[sorted.length - 1] / 1e6,
                Arrays.stream(sorted).count());
    }
}
