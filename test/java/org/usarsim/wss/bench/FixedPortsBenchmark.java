package org.usarsim.wss.bench;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Fixed ports (issue 24, docs/fixed-ports.md) beside a DNS'd port, socat and direct loopback, in
 * one run on one machine: TCP throughput (iperf3) and 64-byte round trips; UDP with iperf3 -u at
 * 200 Mbit/s and the highest rate of a ladder with under 0.1 % loss, beside socat UDP-LISTEN;
 * 64-byte UDP round trips; and the loss table's draw, 100,000 datagrams per row. Needs iperf3
 * and socat. {@code --seconds N --runs N}; docs/performance.md has the command and the figures.
 */
public final class FixedPortsBenchmark {

    private static final InetAddress LOCAL = InetAddress.getLoopbackAddress();
    private static final Pattern TCP_BPS = Pattern.compile("\"sum_received\"\\s*:\\s*\\{[^}]*\"bits_per_second\"\\s*:\\s*([0-9.eE+]+)");
    private static final Pattern UDP_SUM = Pattern.compile("\"sum\"\\s*:\\s*\\{[^}]*?\"bits_per_second\"\\s*:\\s*([0-9.eE+]+)[^}]*?\"lost_percent\"\\s*:\\s*([0-9.eE+-]+)");

    private final int seconds;
    private final int runs;
    private final List<Process> children = new ArrayList<>();

    private FixedPortsBenchmark(int seconds, int runs) {
        this.seconds = seconds;
        this.runs = runs;
    }

    public static void main(String[] args) throws Exception {
        int seconds = 3;
        int runs = 3;
        String only = "";
        for (int i = 0; i < args.length; i += 2) {
            switch (args[i]) {
                case "--seconds" -> seconds = Integer.parseInt(args[i + 1]);
                case "--runs" -> runs = Integer.parseInt(args[i + 1]);
                case "--only" -> only = args[i + 1];
                default -> throw new IllegalArgumentException("--seconds N --runs N --only tcp|udp|loss, not " + args[i]);
            }
        }
        FixedPortsBenchmark bench = new FixedPortsBenchmark(seconds, runs);
        try {
            if (only.isEmpty() || only.equals("tcp")) {
                bench.tcp();
            }
            if (only.isEmpty() || only.equals("udp")) {
                bench.udp();
            }
            if (only.isEmpty() || only.equals("loss")) {
                bench.loss();
            }
        } finally {
            bench.children.forEach(Process::destroy);
        }
    }

    // ---- TCP: a fixed port beside a DNS'd one, socat and direct ----

    private void tcp() throws Exception {
        int iperfPort = free();
        Process iperf = child("iperf3", "-s", "-B", "127.0.0.1", "-p", Integer.toString(iperfPort));
        try (EchoServer echo = new EchoServer(64)) {
            int fixedIperf = free();
            int fixedEcho = free();
            try (WssProcess wss = WssProcess.start("wss.robot.Source=", "wss.robot.Sink=",
                    "wss.fixed=Source->Sink:" + iperfPort + "@" + fixedIperf + ",Source->Sink:" + echo.port() + "@" + fixedEcho);
                    ControlClient sink = new ControlClient(wss.controlPort, "Sink2", iperfPort);
                    ControlClient source = new ControlClient(wss.controlPort, "Source2", 1);
                    ControlClient echoSink = new ControlClient(wss.controlPort, "Echo2", echo.port())) {
                int dnsIperf = dns(source, "Sink2", iperfPort);
                int dnsEcho = dns(source, "Echo2", echo.port());
                int socatIperf = free();
                int socatEcho = free();
                Process socat1 = child("socat", "-b", "65536", "TCP-LISTEN:" + socatIperf + ",bind=127.0.0.1,reuseaddr,fork",
                        "TCP:127.0.0.1:" + iperfPort + ",nodelay");
                Process socat2 = child("socat", "TCP-LISTEN:" + socatEcho + ",bind=127.0.0.1,reuseaddr,fork,nodelay",
                        "TCP:127.0.0.1:" + echo.port() + ",nodelay");
                waitListening(socatIperf);
                waitListening(socatEcho);
                String[] names = {"direct loopback", "socat -b 65536", "WSS, DNS'd port", "WSS, fixed port"};
                int[] iperfPorts = {iperfPort, socatIperf, dnsIperf, fixedIperf};
                double[][] mbs = new double[names.length][runs];
                for (int run = 0; run < runs; run++) {
                    for (int path = 0; path < names.length; path++) {
                        mbs[path][run] = iperfTcp(iperfPorts[path]);
                    }
                }
                System.out.printf("%n## TCP throughput of one stream (iperf3, %d s, median of %d runs, paths in turn)%n%n", seconds, runs);
                System.out.println("| path | MB/s (median) | vs socat | vs DNS'd port |");
                System.out.println("|---|---|---|---|");
                for (int path = 0; path < names.length; path++) {
                    double m = RelayBenchmark.median(mbs[path]);
                    System.out.printf(Locale.ROOT, "| %s | %.0f | %.2fx | %.2fx |%n", names[path], m, m / RelayBenchmark.median(mbs[1]),
                            m / RelayBenchmark.median(mbs[2]));
                }
                int[] echoPorts = {echo.port(), socatEcho, dnsEcho, fixedEcho};
                double[] medians = new double[names.length];
                for (int path = 0; path < names.length; path++) {
                    double best = Double.MAX_VALUE;
                    for (int run = 0; run < runs; run++) {
                        best = Math.min(best, RelayBenchmark.percentile(RelayBenchmark.roundTrips(echoPorts[path], 20_000, false, 2_000), 50));
                    }
                    medians[path] = best / 1e3;
                }
                System.out.printf("%n## TCP round trip of a 64-byte message (20,000 rounds, best median of %d runs)%n%n", runs);
                System.out.println("| path | median µs | added to direct | added vs socat's |");
                System.out.println("|---|---|---|---|");
                for (int path = 0; path < names.length; path++) {
                    double added = medians[path] - medians[0];
                    System.out.printf(Locale.ROOT, "| %s | %.1f | %.1f | %s |%n", names[path], medians[path], added,
                            path >= 2 ? String.format(Locale.ROOT, "%.2fx", added / (medians[1] - medians[0])) : "");
                }
                stop(socat1);
                stop(socat2);
            }
        } finally {
            stop(iperf);
        }
    }

    private static int dns(ControlClient source, String to, int port) throws IOException {
        String reply = source.ask("DNS {Robot " + to + "} {Port " + port + "}");
        Matcher m = Pattern.compile("\\{Port (\\d+)\\}").matcher(reply);
        if (!m.find()) {
            throw new IOException("DNS " + to + ": " + reply);
        }
        return Integer.parseInt(m.group(1));
    }

    /** MB/s received; a run iperf3 could not start (its server still busy with the last one) is tried again, twice at most. */
    private double iperfTcp(int port) throws Exception {
        String json = "";
        for (int attempt = 0; attempt < 3; attempt++) {
            json = run("iperf3", "-c", "127.0.0.1", "-p", Integer.toString(port), "-t", Integer.toString(seconds), "-J");
            Matcher m = TCP_BPS.matcher(json);
            if (m.find()) {
                return Double.parseDouble(m.group(1)) / 8 / 1e6;
            }
            System.err.println("  iperf3 through " + port + " failed, again: " + json.replaceAll("\\s+", " ").replaceAll(".*\"error\"", "error"));
            Thread.sleep(500);
        }
        throw new IOException("no iperf3 result: " + json);
    }

    // ---- UDP: a fixed port beside socat UDP-LISTEN and direct ----

    private void udp() throws Exception {
        int iperfPort = free();
        Process iperf = child("iperf3", "-s", "-B", "127.0.0.1", "-p", Integer.toString(iperfPort));
        try (DatagramSocket echo = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
            Thread echoing = udpEcho(echo);
            int fixedTcp = free();
            int fixedUdp = freeUdp(fixedTcp);
            int fixedEcho = freeUdp(0);
            try (WssProcess wss = WssProcess.start("wss.robot.Source=", "wss.robot.Sink=",
                    "wss.fixed=Source->Sink:" + iperfPort + "@" + fixedTcp + ",udp Source->Sink:" + iperfPort + "@" + fixedUdp
                            + ",udp Source->Sink:" + echo.getLocalPort() + "@" + fixedEcho)) {
                int socatTcp = free();
                int socatUdp = freeUdp(socatTcp);
                int socatEcho = freeUdp(0);
                Process s1 = child("socat", "TCP-LISTEN:" + socatTcp + ",bind=127.0.0.1,reuseaddr,fork", "TCP:127.0.0.1:" + iperfPort);
                Process s2 = child("socat", "-b", "65536", "UDP-LISTEN:" + socatUdp + ",bind=127.0.0.1,reuseaddr,fork",
                        "UDP:127.0.0.1:" + iperfPort);
                Process s3 = child("socat", "UDP-LISTEN:" + socatEcho + ",bind=127.0.0.1,reuseaddr,fork", "UDP:127.0.0.1:" + echo.getLocalPort());
                waitListening(socatTcp);
                String[] names = {"direct loopback", "socat UDP-LISTEN", "WSS, fixed UDP port"};
                int[] tcpPorts = {iperfPort, socatTcp, fixedTcp}; // iperf3's control connection: TCP on the same number
                System.out.printf("%n## UDP through iperf3 -u (%d s, iperf3's default datagram length, -w 4M, median of %d runs, paths in turn)%n%n", seconds, runs);
                System.out.println("| path | at 200 Mbit/s: received Mbit/s, loss % | highest rate of 100, 200, 300, 400, 600, 800, 1000 Mbit/s with < 0.1 % loss (each run) |");
                System.out.println("|---|---|---|");
                for (int path = 0; path < names.length; path++) {
                    double[] got = new double[runs];
                    double[] lost = new double[runs];
                    List<Integer> highest = new ArrayList<>();
                    for (int run = 0; run < runs; run++) {
                        double[] r = iperfUdp(tcpPorts[path], 200);
                        got[run] = r[0];
                        lost[run] = r[1];
                        int best = 0;
                        for (int rate : new int[] {100, 200, 300, 400, 600, 800, 1000}) {
                            if (iperfUdp(tcpPorts[path], rate)[1] < 0.1) {
                                best = rate;
                            } else {
                                break;
                            }
                        }
                        highest.add(best);
                    }
                    System.out.printf(Locale.ROOT, "| %s | %.0f, %.2f %% | %s |%n", names[path], RelayBenchmark.median(got),
                            RelayBenchmark.median(lost), highest);
                }
                int[] echoPorts = {echo.getLocalPort(), socatEcho, fixedEcho};
                System.out.printf("%n## UDP round trip of a 64-byte datagram (20,000 rounds after 2,000, best median of %d runs)%n%n", runs);
                System.out.println("| path | median µs | added to direct | added vs socat's |");
                System.out.println("|---|---|---|---|");
                double[] medians = new double[names.length];
                for (int path = 0; path < names.length; path++) {
                    double best = Double.MAX_VALUE;
                    for (int run = 0; run < runs; run++) {
                        best = Math.min(best, udpRoundTrips(echoPorts[path], 20_000, 2_000));
                    }
                    medians[path] = best;
                }
                for (int path = 0; path < names.length; path++) {
                    double added = medians[path] - medians[0];
                    System.out.printf(Locale.ROOT, "| %s | %.1f | %.1f | %s |%n", names[path], medians[path], added,
                            path == 2 ? String.format(Locale.ROOT, "%.2fx", added / (medians[1] - medians[0])) : "");
                }
                stop(s1);
                stop(s2);
                stop(s3);
            } finally {
                echo.close();
                echoing.join(2000);
            }
        } finally {
            stop(iperf);
        }
    }

    /**
     * Received Mbit/s and loss % of one iperf3 -u run at {@code mbits} (iperf3's default datagram
     * length, 4 MiB socket buffers at both ends as the WSS's own); a run that could not start is tried again, twice at most.
     */
    private double[] iperfUdp(int port, int mbits) throws Exception {
        String json = "";
        for (int attempt = 0; attempt < 3; attempt++) {
            json = run("iperf3", "-c", "127.0.0.1", "-p", Integer.toString(port), "-u", "-b", mbits + "M", "-w", "4M",
                    "-t", Integer.toString(seconds), "-J");
            Matcher m = UDP_SUM.matcher(json);
            if (m.find()) {
                return new double[] {Double.parseDouble(m.group(1)) / 1e6, Double.parseDouble(m.group(2))};
            }
            System.err.println("  iperf3 -u through " + port + " failed, again: " + json.replaceAll("\\s+", " ").replaceAll(".*\"error\"", "error"));
            Thread.sleep(500);
        }
        throw new IOException("no iperf3 -u result: " + json);
    }

    private static Thread udpEcho(DatagramSocket echo) {
        Thread thread = new Thread(() -> {
            byte[] buffer = new byte[65_536];
            DatagramPacket packet = new DatagramPacket(buffer, buffer.length);
            try {
                while (true) {
                    packet.setLength(buffer.length);
                    echo.receive(packet);
                    echo.send(packet);
                }
            } catch (IOException closed) {
                // the benchmark ended
            }
        }, "udp-echo");
        thread.setDaemon(true);
        thread.start();
        return thread;
    }

    /** The median round trip in µs of a 64-byte datagram to {@code port}; a lost one is sent again (counted as its time). */
    private static double udpRoundTrips(int port, int rounds, int warmUp) throws IOException {
        try (DatagramSocket socket = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
            socket.setSoTimeout(1000);
            socket.connect(new InetSocketAddress(LOCAL, port));
            byte[] message = new byte[64];
            DatagramPacket out = new DatagramPacket(message, 64);
            DatagramPacket in = new DatagramPacket(new byte[64], 64);
            long[] rtts = new long[rounds];
            for (int i = -warmUp; i < rounds; i++) {
                long start = System.nanoTime();
                while (true) {
                    socket.send(out);
                    try {
                        socket.receive(in);
                        break;
                    } catch (SocketTimeoutException e) {
                        // lost: again
                    }
                }
                if (i >= 0) {
                    rtts[i] = System.nanoTime() - start;
                }
            }
            return RelayBenchmark.percentile(rtts, 50) / 1e3;
        }
    }

    // ---- loss: the table's draw, 100,000 datagrams per row ----

    /**
     * The Noop model's strength is 0 dBm; a table whose one row is at 0 dBm with a row's percent
     * pins that percent for the pair. Shaped (54 Mbit/s), 100,000 100-byte datagrams sent at a pace
     * the queue never fills at (counted: none dropped by the queue), received by a sink.
     */
    private void loss() throws Exception {
        System.out.println("\n## Loss drawn for the loss table's rows (100,000 datagrams of 100 bytes each, shaped at 54 Mbit/s)\n");
        System.out.println("| row's percent | sent | received by the relay | lost to the signal (relay's count) | received by the sink"
                + " | dropped elsewhere (kernel, queue) | measured loss % of what the relay received | off by (points) |");
        System.out.println("|---|---|---|---|---|---|---|---|");
        for (double percent : new double[] {1, 10, 50}) {
            try (DatagramSocket sink = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
                sink.setReceiveBufferSize(8 << 20);
                int fixed = freeUdp(0);
                try (WssProcess wss = WssProcess.start("wss.robot.Source=", "wss.robot.Sink=", "wss.shaping=on", "wss.statsInterval=1",
                        "wss.shaping.loss=0:" + percent, "wss.fixed=udp Source->Sink:" + sink.getLocalPort() + "@" + fixed);
                        DatagramSocket source = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
                    int[] received = {0};
                    Thread counting = new Thread(() -> {
                        DatagramPacket packet = new DatagramPacket(new byte[200], 200);
                        try {
                            sink.setSoTimeout(3000);
                            while (true) {
                                sink.receive(packet);
                                received[0]++;
                            }
                        } catch (IOException done) {
                            // three seconds of silence: all that comes has come
                        }
                    });
                    counting.start();
                    byte[] data = new byte[100];
                    DatagramPacket packet = new DatagramPacket(data, 100, LOCAL, fixed);
                    long start = System.nanoTime();
                    int sent = 100_000;
                    for (int i = 0; i < sent; i++) {
                        source.send(packet);
                        long due = start + i * 100_000L; // 10,000 a second: 8 Mbit/s of payload, far under the rate
                        while (System.nanoTime() - due < 0) {
                            Thread.onSpinWait();
                        }
                    }
                    counting.join(TimeUnit.SECONDS.toMillis(30));
                    // the statistics line: udp from > to, datagrams, bytes, dropped broken, dropped queue, lost signal
                    String[] line = wss.lastLineContaining("Source > Sink").trim().split("\\s+");
                    long relayed = Long.parseLong(line[3]);
                    long droppedQueue = Long.parseLong(line[6]);
                    long lost = Long.parseLong(line[7]);
                    long reached = relayed + droppedQueue + lost;
                    double measured = 100.0 * lost / (relayed + lost);
                    System.out.printf(Locale.ROOT, "| %.0f | %d | %d | %d | %d | %d | %.2f | %.2f |%n", percent, sent, reached, lost,
                            received[0], sent - received[0] - lost, measured, Math.abs(measured - percent));
                }
            }
        }
    }

    // ---- processes and ports ----

    private Process child(String... command) throws IOException {
        Process process = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.DISCARD)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        children.add(process);
        return process;
    }

    private String run(String... command) throws Exception {
        Process process = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        String out = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        process.waitFor(seconds + 30L, TimeUnit.SECONDS);
        return out;
    }

    private static void stop(Process process) throws InterruptedException {
        process.destroy();
        process.waitFor(5, TimeUnit.SECONDS);
    }

    private static int free() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, LOCAL)) {
            return socket.getLocalPort();
        }
    }

    /** A number free for UDP: {@code tcp}'s when it is (0: any). */
    private static int freeUdp(int tcp) throws IOException {
        try (DatagramSocket socket = new DatagramSocket(new InetSocketAddress(LOCAL, tcp))) {
            return socket.getLocalPort();
        }
    }

    private static void waitListening(int port) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (System.nanoTime() - deadline < 0) {
            try (java.net.Socket probe = new java.net.Socket(LOCAL, port)) {
                return;
            } catch (IOException notYet) {
                Thread.sleep(20);
            }
        }
        throw new IOException("nothing listens on " + port);
    }
}
