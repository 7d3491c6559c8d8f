package org.usarsim.wss.bench;

import java.io.InputStream;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.shaping.Bitrate;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * Issue 34, "the bound against reality" (docs/routes.md, docs/performance.md): links shaped over
 * shared airtime, a chain of robots R0 .. Rk whose pairs are forced up with the rates given (every
 * other pair forced down), the relays real programs: robot Ri's server is
 * {@code socat TCP-LISTEN:pi TCP:127.0.0.1:W} with W the WSS port of Ri to R(i+1), so what Ri
 * receives it sends on over its own DNS'd port. R0 sends as fast as TCP lets it to R1; Rk counts
 * what arrives. The throughput measured over {@code --seconds} (after 2 s of warm-up) against the
 * route's rate as the hub computes it ({@code Hub.routes()}). Needs socat on the PATH.
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.RouteRelayBenchmark [--seconds 10] [--relay-buffer BYTES] [--relay-block BYTES] 6M 12M,6M 12M,6M,12M
 * </pre>
 * Each argument is one chain: its hops' rates in order. {@code --relay-buffer} sets the relays'
 * socket buffers, {@code --relay-block} the most socat passes on at once ({@code -b}, 8,192 by default).
 */
public final class RouteRelayBenchmark {

    private RouteRelayBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        int seconds = 10;
        String buffers = "";
        String block = "8192";
        List<String> chains = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            if (args[i].equals("--seconds")) {
                seconds = Integer.parseInt(args[++i]);
            } else if (args[i].equals("--relay-block")) {
                block = args[++i];
            } else if (args[i].equals("--relay-buffer")) {
                buffers = ",rcvbuf=" + args[++i] + ",sndbuf=" + args[i];
            } else {
                chains.add(args[i]);
            }
        }
        if (chains.isEmpty()) {
            chains = List.of("6M", "12M,6M", "12M,6M,12M", "12M,12M,12M");
        }
        System.out.println("| hops | rates (bit/s) | route | computed | measured | measured / computed |");
        System.out.println("|---|---|---|---|---|---|");
        for (String chain : chains) {
            List<Long> rates = new ArrayList<>();
            for (String rate : chain.split(",")) {
                rates.add(Bitrate.parse(rate));
            }
            run(rates, seconds, buffers, block);
        }
        System.exit(0);
    }

    /** Waits until something listens on 127.0.0.1:{@code port} (socat started), no later than {@code deadline}. */
    private static void awaitListening(int port, long deadline) throws InterruptedException {
        while (true) {
            try (ServerSocket probe = new ServerSocket()) {
                probe.bind(new java.net.InetSocketAddress("127.0.0.1", port));
            } catch (java.io.IOException e) {
                return; // taken: socat listens (binding leaves no connection behind, unlike a probe connect)
            }
            if (System.nanoTime() - deadline > 0) {
                throw new IllegalStateException("socat is not listening on " + port + " after 10 s");
            }
            Thread.sleep(10);
        }
    }

    private static void run(List<Long> rates, int seconds, String buffers, String block) throws Exception {
        int hops = rates.size();
        HubConfig config = TestHub.config(false, 65536, 600, 1000, 30)
                .withShaping(new ShapingConfig(true, RateTable.DEFAULT, ShapingConfig.DEFAULT_DELAY_MS, true), Map.of());
        List<TestRobot> robots = new ArrayList<>();
        List<Process> relays = new ArrayList<>();
        try (TestHub server = new TestHub(new NoopPropagationModel(), config); ServerSocket sink = new ServerSocket(0)) {
            for (int i = 0; i <= hops; i++) {
                for (int j = i + 1; j <= hops; j++) {
                    if (j == i + 1) {
                        server.hub.force("R" + i, "R" + j, Force.UP, new RatePin(rates.get(i), -1));
                    } else {
                        server.hub.force("R" + i, "R" + j, Force.DOWN);
                    }
                }
            }
            int[] ports = new int[hops + 1];
            for (int i = 1; i < hops; i++) {
                try (ServerSocket free = new ServerSocket(0)) {
                    ports[i] = free.getLocalPort();
                }
            }
            ports[hops] = sink.getLocalPort();
            for (int i = 0; i <= hops; i++) {
                TestRobot robot = server.robot();
                robots.add(robot);
                robot.init("R" + i, i == 0 ? 4999 : ports[i]);
            }
            int first = robots.get(0).dns("R1", ports[1]);
            for (int i = 1; i < hops; i++) {
                int next = robots.get(i).dns("R" + (i + 1), ports[i + 1]);
                Process socat = new ProcessBuilder("socat", "-b", block, "TCP-LISTEN:" + ports[i] + ",bind=127.0.0.1,reuseaddr,fork" + buffers,
                        "TCP:127.0.0.1:" + next + buffers).redirectErrorStream(true).start();
                relays.add(socat);
            }
            for (int i = 1; i < hops; i++) {
                awaitListening(ports[i], System.nanoTime() + TimeUnit.SECONDS.toNanos(10));
            }
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            Route route = server.hub.routes().route("R0", "R" + hops);
            while (route.hops() != hops && System.nanoTime() < deadline) {
                Thread.sleep(20);
                route = server.hub.routes().route("R0", "R" + hops);
            }
            AtomicLong received = new AtomicLong();
            Thread reader = new Thread(() -> {
                try (Socket in = sink.accept(); InputStream stream = in.getInputStream()) {
                    byte[] buffer = new byte[65536];
                    int n;
                    while ((n = stream.read(buffer)) >= 0) {
                        received.addAndGet(n);
                    }
                } catch (Exception e) {
                    // the end of the run
                }
            }, "sink");
            reader.setDaemon(true);
            reader.start();
            Socket out = robots.get(0).connect(first);
            Thread writer = new Thread(() -> {
                byte[] chunk = new byte[16384];
                try (OutputStream stream = out.getOutputStream()) {
                    while (true) {
                        stream.write(chunk);
                    }
                } catch (Exception e) {
                    // the end of the run
                }
            }, "source");
            writer.setDaemon(true);
            writer.start();
            Thread.sleep(2000);
            long fromBytes = received.get();
            long from = System.nanoTime();
            Thread.sleep(TimeUnit.SECONDS.toMillis(seconds));
            long bytes = received.get() - fromBytes;
            double elapsed = (System.nanoTime() - from) / 1e9;
            out.close();
            double measured = bytes * 8 / elapsed;
            System.out.printf(Locale.ROOT, "| %d | %s | %s | %s | %s | %.3f |%n", hops, rates.stream().map(Bitrate::format).toList(),
                    route.pathText(), Bitrate.format(route.rateBound()), Bitrate.format((long) measured), measured / route.rateBound());
        } finally {
            relays.forEach(Process::destroy);
            for (TestRobot robot : robots) {
                robot.close();
            }
        }
    }
}
