package org.usarsim.wss.bench;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/**
 * Robots in full mesh on one machine (issue 18, docs/performance.md): every robot asks DNS for
 * every other. Sections ({@code --only}):
 * <ul>
 * <li>{@code dns}: the WSS as its own process (under {@code --limit} descriptors), N robots
 * register and ask all N(N-1) DNS at once ({@link MeshAsker}); how many were answered with a
 * port, how long all took, the server's threads, descriptors and resident memory;</li>
 * <li>{@code break}: a hub in this JVM with the same mesh; the model's breaks of one robot with
 * every other (2(N-1) ports stop listening), then its resumes, timed, for {@code --rounds}
 * robots: in one go ({@code applyLinkStates}, as the simulator models do) and pair by pair (as
 * a model that calls {@code breakConnectionsForPair} for each); then a robot leaving (its ports
 * drain and stop in one step);</li>
 * <li>{@code traffic}: the WSS process, the mesh, and one connection per pair of robots (every
 * {@code --every}th pair, where the descriptors do not allow all) forwarding {@code --rate}
 * bytes a second for {@code --seconds}, every byte checksummed; meanwhile every robot asks GETSS
 * every 100 ms: its reply times;</li>
 * <li>{@code churn}: the WSS process under {@code --limit} descriptors (1,024 by default there)
 * with the default port memory; {@code --robots} robots with new names one after another: INIT,
 * DNS a base robot, connect and send a line through the port, leave. How many were refused.</li>
 * </ul>
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.MeshBenchmark --only dns --robots 100 --limit 20000
 * </pre>
 */
public final class MeshBenchmark {

    private MeshBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        String only = "dns";
        int robots = 100;
        int limit = 0;
        int rounds = 10;
        int seconds = 20;
        int every = 1;
        long rate = 64 * 1024;
        int warmUp = 0;
        int hold = 0;
        String classes = null;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--only" -> only = args[++i];
                case "--robots" -> robots = Integer.parseInt(args[++i]);
                case "--limit" -> limit = Integer.parseInt(args[++i]);
                case "--rounds" -> rounds = Integer.parseInt(args[++i]);
                case "--seconds" -> seconds = Integer.parseInt(args[++i]);
                case "--every" -> every = Integer.parseInt(args[++i]);
                case "--rate" -> rate = Long.parseLong(args[++i]);
                case "--warmup" -> warmUp = Integer.parseInt(args[++i]);
                case "--classes" -> classes = args[++i];
                case "--hold" -> hold = Integer.parseInt(args[++i]);
                default -> throw new IllegalArgumentException("unknown argument " + args[i]);
            }
        }
        System.out.printf("WSS mesh benchmark: %d cores, %s, %s, %d robots, %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name") + " " + System.getProperty("java.version"), only, robots,
                java.time.LocalDateTime.now());
        switch (only) {
            case "dns" -> dns(robots, limit, warmUp, hold, classes);
            case "break" -> breaks(robots, rounds);
            case "traffic" -> traffic(robots, limit, every, rate, seconds);
            case "churn" -> churn(robots, limit == 0 ? 1024 : limit, classes);
            default -> throw new IllegalArgumentException("unknown section " + only);
        }
        System.exit(0);
    }

    /** The mesh's own cap: every port of the mesh comes from this one address. */
    private static String perAddress(int robots) {
        return "wss.maxPortsPerAddress=" + Math.max(HubConfig.MAX_PORTS_PER_ADDRESS, robots * (robots - 1));
    }

    // ---- dns ----

    /** This build's classes, or another build's ({@code --classes}: a build before this change knows no wss.maxPortsPerAddress). */
    private static WssProcess wss(String classes, int limit, String... properties) throws Exception {
        if (classes == null) {
            String own = java.nio.file.Path.of(org.usarsim.wss.app.Main.class.getProtectionDomain().getCodeSource().getLocation().toURI())
                    .toString();
            return WssProcess.start(own, limit, properties);
        }
        System.out.println("  the WSS from " + classes);
        return WssProcess.start(classes, limit, java.util.Arrays.stream(properties)
                .filter(property -> !property.startsWith("wss.maxPortsPerAddress")).toArray(String[]::new));
    }

    /** @param hold seconds to wait after the mesh before the robots leave (to look at the server: a profiler, strace) */
    private static void dns(int robots, int limit, int warmUp, int hold, String classes) throws Exception {
        try (WssProcess wss = wss(classes, limit, perAddress(robots))) {
            System.out.printf("  descriptor limit of the WSS: %s; wss.maxPortsPerAddress: %s%n", limit > 0 ? limit : "the shell's",
                    perAddress(robots));
            row("at start", ProcessStats.of(wss.pid()));
            if (warmUp > 0) {
                // Another mesh first, gone before the measured one: the JIT has compiled the DNS path.
                List<ControlClient> warm = register(wss.controlPort, warmUp, i -> 5000, "W");
                Mesh mesh = askAll(warm, "W");
                for (ControlClient client : warm) {
                    client.close();
                }
                System.out.printf(Locale.ROOT, "  warm-up: %d robots asked %d DNS in %.2f s and left (their %d ports are remembered)%n",
                        warmUp, mesh.asked(), mesh.seconds(), mesh.answered());
                row("after the warm-up", ProcessStats.of(wss.pid()));
            }
            List<ControlClient> clients = register(wss.controlPort, robots, i -> 5000);
            ProcessStats registered = ProcessStats.of(wss.pid());
            row(robots + " robots registered", registered);
            double serverCpu = ProcessStats.cpuSeconds(wss.pid());
            double ownCpu = ProcessStats.cpuSeconds(ProcessHandle.current().pid());
            java.util.Map<String, Long> serverThreads = ProcessStats.cpuByKind(wss.pid());
            Mesh mesh = askAll(clients);
            System.out.printf(Locale.ROOT, "  %d DNS in %.2f s: %d answered with a port, %d refused (CPU meanwhile: the WSS %.2f s,"
                    + " the robots %.2f s)%n", mesh.asked(), mesh.seconds(), mesh.answered(), mesh.refused(),
                    ProcessStats.cpuSeconds(wss.pid()) - serverCpu, ProcessStats.cpuSeconds(ProcessHandle.current().pid()) - ownCpu);
            System.out.println("  the WSS's CPU by thread: " + ProcessStats.cpuBetween(serverThreads, ProcessStats.cpuByKind(wss.pid())));
            Set<Integer> listening = ListeningPorts.now();
            long listens = mesh.numbers().stream().filter(listening::contains).count();
            System.out.printf("  WSS ports listening (/proc/net/tcp): %d of %d%n", listens, mesh.answered());
            ProcessStats after = ProcessStats.of(wss.pid());
            row("after every DNS", after);
            System.out.printf(Locale.ROOT, "  threads %d (target at most %d); descriptors %d, %.2f a port (the mesh's, beyond those"
                    + " before it and its %d control connections)%n", after.threads(), 100 + robots, after.descriptors(),
                    (after.descriptors() - registered.descriptors()) / (double) Math.max(1, mesh.answered()), robots);
            if (hold > 0) {
                System.out.println("  holding the mesh for " + hold + " s");
                Thread.sleep(TimeUnit.SECONDS.toMillis(hold));
            }
            for (ControlClient client : clients) {
                client.close();
            }
        }
    }

    private interface AcceptPort {
        int of(int robot) throws IOException;
    }

    private static List<ControlClient> register(int controlPort, int robots, AcceptPort acceptPort) throws IOException {
        return register(controlPort, robots, acceptPort, "R");
    }

    private static List<ControlClient> register(int controlPort, int robots, AcceptPort acceptPort, String prefix) throws IOException {
        List<ControlClient> clients = new ArrayList<>();
        for (int i = 0; i < robots; i++) {
            clients.add(new ControlClient(controlPort, prefix + i, acceptPort.of(i)));
        }
        return clients;
    }

    /** The DNS of all pairs: numbers[i][j] the port from Ri to Rj (0: refused). */
    private record Mesh(int[][] ports, int asked, int answered, int refused, double seconds) {
        List<Integer> numbers() {
            List<Integer> numbers = new ArrayList<>();
            for (int[] row : ports) {
                for (int number : row) {
                    if (number > 0) {
                        numbers.add(number);
                    }
                }
            }
            return numbers;
        }
    }

    /** Every robot asks DNS for every other, all at once ({@link MeshAsker}). */
    private static Mesh askAll(List<ControlClient> clients) throws IOException {
        return askAll(clients, "R");
    }

    private static Mesh askAll(List<ControlClient> clients, String prefix) throws IOException {
        MeshAsker.Answers answers = MeshAsker.askAll(clients, prefix);
        System.out.println("  each tenth of the replies in (s): " + java.util.Arrays.stream(answers.tenths())
                .mapToObj(t -> String.format(Locale.ROOT, "%.2f", t)).collect(java.util.stream.Collectors.joining(" ")));
        if (answers.firstRefusal() != null) {
            System.out.println("  first refusal: " + answers.firstRefusal());
        }
        int robots = clients.size();
        int asked = robots * (robots - 1);
        return new Mesh(answers.ports(), asked, asked - answers.refused(), answers.refused(), answers.seconds());
    }

    private static void row(String when, ProcessStats stats) {
        System.out.printf(Locale.ROOT, "  %-40s threads %6d (server's %6d)  descriptors %6d  resident %5d MiB%n", when,
                stats.threads(), stats.serverThreads(), stats.descriptors(), stats.residentKiB() / 1024);
    }

    // ---- break ----

    private static void breaks(int robots, int rounds) throws Exception {
        HubConfig config = TestHub.config(true, 65536, 600, 1000, 30)
                .withMaxPortsPerAddress(Math.max(HubConfig.MAX_PORTS_PER_ADDRESS, robots * (robots - 1)));
        java.util.logging.Logger.getLogger("").setLevel(java.util.logging.Level.WARNING);
        Hub hub = new Hub(config, new NoopPropagationModel());
        hub.start();
        try {
            List<ControlClient> clients = register(hub.controlPort(), robots, i -> 5000);
            Mesh mesh = askAll(clients);
            System.out.printf(Locale.ROOT, "  the mesh: %d DNS in %.2f s, %d answered%n", mesh.asked(), mesh.seconds(), mesh.answered());
            for (boolean together : new boolean[] {true, false}) {
                String how = together ? "in one go (applyLinkStates, as the simulator models do)"
                        : "pair by pair (breakConnectionsForPair, as a model that does not batch)";
                System.out.println("  a robot out of range of every other, " + how + ":");
                setLinks(hub, robots, robots - 2, false, together); // unmeasured: the JIT compiles the path
                setLinks(hub, robots, robots - 2, true, together);
                List<Double> breakMs = new ArrayList<>();
                List<Double> resumeMs = new ArrayList<>();
                for (int round = 0; round < Math.min(rounds, robots - 2); round++) {
                    String robot = "R" + round;
                    List<Integer> ofRobot = portsOf(mesh, round);
                    long start = System.nanoTime();
                    setLinks(hub, robots, round, false, together);
                    breakMs.add((System.nanoTime() - start) / 1e6);
                    Set<Integer> listening = ListeningPorts.now();
                    long still = ofRobot.stream().filter(listening::contains).count();
                    long accepted = ofRobot.stream().filter(MeshBenchmark::accepts).count();
                    start = System.nanoTime();
                    setLinks(hub, robots, round, true, together);
                    resumeMs.add((System.nanoTime() - start) / 1e6);
                    listening = ListeningPorts.now();
                    long again = ofRobot.stream().filter(listening::contains).count();
                    System.out.printf(Locale.ROOT, "    %s: %d ports stopped in %.1f ms (listening after: %d, connects accepted: %d);"
                            + " resumed in %.1f ms (listening again: %d)%n", robot, ofRobot.size(), breakMs.get(breakMs.size() - 1),
                            still, accepted, resumeMs.get(resumeMs.size() - 1), again);
                }
                System.out.printf(Locale.ROOT, "    break of %d ports: median %.1f ms, max %.1f ms; resume: median %.1f ms, max %.1f ms%n",
                        2 * (robots - 1), median(breakMs), max(breakMs), median(resumeMs), max(resumeMs));
            }
            // A robot leaving: its ports drain and stop in one step.
            String leaver = "R" + (robots - 1);
            List<Integer> ofLeaver = portsOf(mesh, robots - 1);
            java.util.concurrent.CountDownLatch gone = new java.util.concurrent.CountDownLatch(1);
            hub.addListener(new org.usarsim.wss.model.WssEventListener() {
                @Override
                public void robotDeregistered(String robot) {
                    if (robot.equals(leaver)) {
                        gone.countDown(); // delivered once the departure's ports have stopped
                    }
                }
            });
            long start = System.nanoTime();
            clients.get(robots - 1).close();
            gone.await();
            double leftMs = (System.nanoTime() - start) / 1e6;
            Set<Integer> listening = ListeningPorts.now();
            System.out.printf(Locale.ROOT, "  %s left: drained and deregistered in %.1f ms, %d of its %d ports still listening%n", leaver,
                    leftMs, ofLeaver.stream().filter(listening::contains).count(), ofLeaver.size());
            hub.close(); // before the robots leave: 99 departures at once would drain 9,702 ports in this JVM, robots and all
            for (ControlClient client : clients) {
                client.close();
            }
        } finally {
            hub.close();
        }
    }

    /** The model's verdict on every pair of the robot: in range or not, in one go or pair by pair. */
    private static void setLinks(Hub hub, int robots, int robot, boolean live, boolean together) {
        java.util.Map<org.usarsim.wss.model.RobotPair, Boolean> inRange = new java.util.LinkedHashMap<>();
        for (int other = 0; other < robots; other++) {
            if (other != robot) {
                inRange.put(org.usarsim.wss.model.RobotPair.of("R" + robot, "R" + other), live);
            }
        }
        if (together) {
            hub.robotLinks().applyLinkStates(inRange);
            return;
        }
        inRange.keySet().forEach(pair -> {
            if (live) {
                hub.robotLinks().resumeConnectionsForPair(pair.first(), pair.second());
            } else {
                hub.robotLinks().breakConnectionsForPair(pair.first(), pair.second());
            }
        });
    }

    /** The ports the robot is the source or the target of. */
    private static List<Integer> portsOf(Mesh mesh, int robot) {
        List<Integer> numbers = new ArrayList<>();
        for (int other = 0; other < mesh.ports().length; other++) {
            if (other != robot) {
                numbers.add(mesh.ports()[robot][other]);
                numbers.add(mesh.ports()[other][robot]);
            }
        }
        return numbers;
    }

    private static boolean accepts(int port) {
        try (Socket socket = new Socket()) {
            socket.connect(new InetSocketAddress("127.0.0.1", port), 1000);
            return true;
        } catch (ConnectException refused) {
            return false;
        } catch (IOException e) {
            return true;
        }
    }

    private static double median(List<Double> values) {
        List<Double> sorted = values.stream().sorted().toList();
        return sorted.get(sorted.size() / 2);
    }

    private static double max(List<Double> values) {
        return values.stream().mapToDouble(Double::doubleValue).max().orElse(0);
    }

    // ---- traffic ----

    private static void traffic(int robots, int limit, int every, long rate, int seconds) throws Exception {
        try (WssProcess wss = wss(null, limit, perAddress(robots))) {
            MeshStreams streams = new MeshStreams(rate);
            List<Integer> accepting = new ArrayList<>();
            for (int i = 0; i < robots; i++) {
                accepting.add(streams.accepting());
            }
            streams.startReading();
            List<ControlClient> clients = register(wss.controlPort, robots, accepting::get);
            Mesh mesh = askAll(clients);
            System.out.printf(Locale.ROOT, "  the mesh: %d DNS in %.2f s, %d answered%n", mesh.asked(), mesh.seconds(), mesh.answered());
            int pair = 0;
            long opened = System.nanoTime();
            for (int i = 0; i < robots; i++) {
                for (int j = i + 1; j < robots; j++) {
                    if (pair++ % every == 0) {
                        streams.open(mesh.ports()[i][j]);
                    }
                }
            }
            int arrived = streams.awaitArrived(120);
            System.out.printf(Locale.ROOT, "  %d of the %d pairs hold a connection, %d bytes a second each; all forwarded to their"
                    + " targets %.1f s after the first was opened (%d of them)%n", streams.streams(), pair, rate,
                    (System.nanoTime() - opened) / 1e9, arrived);
            GetssProbe probe = new GetssProbe(clients);
            double serverCpu = ProcessStats.cpuSeconds(wss.pid());
            double ownCpu = ProcessStats.cpuSeconds(ProcessHandle.current().pid());
            long started = System.nanoTime();
            streams.startWriting();
            probe.start();
            Thread.sleep(TimeUnit.SECONDS.toMillis(seconds) / 2);
            ProcessStats during = ProcessStats.of(wss.pid());
            Thread.sleep(TimeUnit.SECONDS.toMillis(seconds) / 2);
            probe.stop();
            double wall = (System.nanoTime() - started) / 1e9;
            row("during the streams", during);
            System.out.printf(Locale.ROOT, "  CPU during the %.1f s of streams: the WSS %.1f s (%.2f cores), the robots %.1f s (%.2f cores)%n",
                    wall, ProcessStats.cpuSeconds(wss.pid()) - serverCpu, (ProcessStats.cpuSeconds(wss.pid()) - serverCpu) / wall,
                    ProcessStats.cpuSeconds(ProcessHandle.current().pid()) - ownCpu,
                    (ProcessStats.cpuSeconds(ProcessHandle.current().pid()) - ownCpu) / wall);
            MeshStreams.Outcome outcome = streams.finish(30);
            System.out.printf(Locale.ROOT, "  streams: %d, written %.1f MB (%.1f MB due at the rate), received %.1f MB; whole %d,"
                    + " damaged %d, unfinished %d%n", outcome.streams(), outcome.written() / 1e6, outcome.dueBytes() / 1e6,
                    outcome.received() / 1e6, outcome.whole(), outcome.damaged(), outcome.unfinished());
            System.out.println("  GETSS meanwhile: " + probe.summary());
            for (ControlClient client : clients) {
                client.close();
            }
        }
    }

    // ---- churn ----

    private static void churn(int robots, int limit, String classes) throws Exception {
        try (WssProcess wss = wss(classes, limit, "wss.logLevel=INFO");
             java.net.ServerSocket baseAccepts = new java.net.ServerSocket(0, 50, java.net.InetAddress.getByName("127.0.0.1"))) {
            System.out.printf("  descriptor limit of the WSS: %d; wss.portMemory: the default (600 s)%n", limit);
            baseAccepts.setSoTimeout(5000);
            ControlClient base = new ControlClient(wss.controlPort, "Base", baseAccepts.getLocalPort());
            int refused = 0;
            int delivered = 0;
            long start = System.nanoTime();
            for (int i = 0; i < robots; i++) {
                try (ControlClient robot = new ControlClient(wss.controlPort, "Fresh" + i, 5000)) {
                    int port = robot.dns("Base");
                    try (Socket data = new Socket("127.0.0.1", port); Socket arrived = baseAccepts.accept()) {
                        data.getOutputStream().write(("robot " + i + "\n").getBytes(java.nio.charset.StandardCharsets.US_ASCII));
                        byte[] line = arrived.getInputStream().readNBytes(("robot " + i + "\n").length());
                        if (new String(line, java.nio.charset.StandardCharsets.US_ASCII).equals("robot " + i + "\n")) {
                            delivered++;
                        }
                    }
                } catch (IOException e) {
                    if (refused++ < 3) {
                        System.out.println("  Fresh" + i + " refused: " + e.getMessage());
                    }
                }
            }
            double took = (System.nanoTime() - start) / 1e9;
            System.out.printf(Locale.ROOT, "  %d robots with new names in %.1f s: %d refused, %d lines delivered; the WSS gave back"
                    + " remembered ports %d times ('descriptors ran short')%n", robots, took, refused, delivered,
                    wss.linesContaining("descriptors ran short"));
            row("after the churn", ProcessStats.of(wss.pid()));
            base.close();
        }
    }
}
