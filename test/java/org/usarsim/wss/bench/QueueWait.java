package org.usarsim.wss.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
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
import org.usarsim.wss.shaping.Bitrate;

/**
 * Issue 27: how long a 64-byte message waits behind a saturating stream, through a shaped WSS
 * pair and through Linux's tbf at the same rate, side by side. A sender writes zeros flat out;
 * after {@link #SATURATE_NS} it writes a 64-byte marker (bytes 1 to 64) every
 * {@link #EVERY_NS}, {@link #MARKERS} times, still writing zeros between them; the receiver
 * notes when each marker's first byte arrives. The wait is from the marker's write call to its
 * arrival, on one clock (System.nanoTime is CLOCK_MONOTONIC, the same for every process).
 *
 * <p>tbf runs on a veth pair of its own, one end in a network namespace ({@code wssq-bench},
 * addresses 10.213.27.1 and .2), the sender a JVM in the namespace; it needs root, {@code ip}
 * and {@code tc}, and is removed after. The WSS run uses {@code wss.force.up=A:B:RATE:2}.
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.QueueWait [1M 6M 24M]
 * </pre>
 */
public final class QueueWait {

    static final long SATURATE_NS = TimeUnit.SECONDS.toNanos(4);
    static final long EVERY_NS = TimeUnit.SECONDS.toNanos(2);
    static final int MARKERS = 3;
    private static final String NAMESPACE = "wssq-bench";
    private static final String HOST = "10.213.27.1";
    private static final String PEER = "10.213.27.2";

    private QueueWait() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length == 4 && args[0].equals("sender")) {
            for (long marked : send(new InetSocketAddress(args[1], Integer.parseInt(args[2])), Integer.parseInt(args[3]))) {
                System.out.println("MARKER " + marked);
            }
            return;
        }
        List<String> rates = args.length == 0 ? List.of("1M", "6M", "24M") : List.of(args);
        boolean tbf = tbfPossible();
        for (int sendBuffer : new int[] {0, 64 * 1024}) {
            table(rates, tbf, sendBuffer);
        }
        System.exit(0);
    }

    /** One table: each rate through the WSS and through tbf, the sender's send buffer {@code sendBuffer} (0: the OS's). */
    private static void table(List<String> rates, boolean tbf, int sendBuffer) throws Exception {
        System.out.printf("%n## Queue: a 64-byte message behind a saturating stream (%d markers, 2 s apart, after 4 s; the sender's"
                + " send buffer %s; load average %s)%n%n", MARKERS, sendBuffer == 0 ? "the OS's" : sendBuffer + " bytes",
                Files.readString(Path.of("/proc/loadavg")).strip());
        System.out.println("| rate | WSS (delay 2 ms; " + System.getProperty("wss.bench.properties", "wss.shaping.queueMs=100").strip()
                + "): waits, s | tbf (latency 100ms): waits, s | WSS median / tbf median |");
        System.out.println("|---|---|---|---|");
        for (String rate : rates) {
            long[] wss = throughWss(rate, sendBuffer);
            long[] viaTbf = tbf ? throughTbf(rate, sendBuffer) : null;
            System.out.printf(Locale.ROOT, "| %s | %s | %s | %s |%n", Bitrate.format(Bitrate.parse(rate)), seconds(wss),
                    viaTbf == null ? "(no tbf here)" : seconds(viaTbf),
                    viaTbf == null || median(wss) < 0 ? "" : String.format(Locale.ROOT, "**%.2f**", (double) median(wss) / median(viaTbf)));
        }
    }

    private static String seconds(long[] waits) {
        StringBuilder text = new StringBuilder();
        for (long wait : waits) {
            text.append(text.length() == 0 ? "" : ", ").append(wait < 0 ? "none within 60 s of the end"
                    : String.format(Locale.ROOT, "%.3f", wait / 1e9));
        }
        return text.toString();
    }

    private static long median(long[] waits) {
        long[] sorted = waits.clone();
        Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }

    /** Through a WSS pinned to {@code rate}: the sender is a thread here. */
    private static long[] throughWss(String rate, int sendBuffer) throws Exception {
        try (WssProcess wss = WssProcess.start("wss.shaping=on", "wss.force.up=A:B:" + rate + ":2");
                Receiver receiver = new Receiver(InetAddress.getLoopbackAddress());
                ControlClient robotB = new ControlClient(wss.controlPort, "B", receiver.port());
                ControlClient robotA = new ControlClient(wss.controlPort, "A", 1)) {
            int port = robotA.dns("B");
            long[] marked = send(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), sendBuffer);
            return receiver.waits(marked);
        }
    }

    /** Through tbf at {@code rate} on a veth pair: the sender is a JVM in the namespace. */
    private static long[] throughTbf(String rate, int sendBuffer) throws Exception {
        long bits = Bitrate.parse(rate);
        try {
            run("ip", "netns", "add", NAMESPACE);
            run("ip", "link", "add", "wssq0", "type", "veth", "peer", "name", "wssq1");
            run("ip", "link", "set", "wssq1", "netns", NAMESPACE);
            run("ip", "addr", "add", HOST + "/30", "dev", "wssq0");
            run("ip", "link", "set", "wssq0", "up");
            run("ip", "netns", "exec", NAMESPACE, "ip", "addr", "add", PEER + "/30", "dev", "wssq1");
            run("ip", "netns", "exec", NAMESPACE, "ip", "link", "set", "wssq1", "up");
            run("ip", "netns", "exec", NAMESPACE, "ip", "link", "set", "lo", "up");
            long burst = Math.max(1600, bits / 8 / 100); // 10 ms at the rate, a frame at least
            run("ip", "netns", "exec", NAMESPACE, "tc", "qdisc", "add", "dev", "wssq1", "root", "tbf", "rate", bits + "bit",
                    "burst", String.valueOf(burst), "latency", "100ms");
            try (Receiver receiver = new Receiver(InetAddress.getByName(HOST))) {
                Process sender = new ProcessBuilder("ip", "netns", "exec", NAMESPACE, Path.of(System.getProperty("java.home"), "bin", "java")
                        .toString(), "-cp", System.getProperty("java.class.path"), QueueWait.class.getName(), "sender", HOST,
                        String.valueOf(receiver.port()), String.valueOf(sendBuffer)).redirectErrorStream(true).start();
                List<Long> marked = new ArrayList<>();
                try (BufferedReader out = new BufferedReader(new InputStreamReader(sender.getInputStream(), StandardCharsets.UTF_8))) {
                    String line;
                    while ((line = out.readLine()) != null) {
                        if (line.startsWith("MARKER ")) {
                            marked.add(Long.parseLong(line.substring(7)));
                        } else {
                            System.out.println("sender: " + line);
                        }
                    }
                }
                sender.waitFor(30, TimeUnit.SECONDS);
                return receiver.waits(marked.stream().mapToLong(Long::longValue).toArray());
            }
        } finally {
            runQuietly("ip", "netns", "del", NAMESPACE); // takes wssq1, and wssq0 with it
            runQuietly("ip", "link", "del", "wssq0");
        }
    }

    /** Whether tbf can be set up here: root, ip and tc, and no namespace of that name already (someone else's). */
    private static boolean tbfPossible() {
        try {
            return "root".equals(System.getProperty("user.name")) && run("tc", "-V") == 0
                    && !new String(new ProcessBuilder("ip", "netns", "list").start().getInputStream().readAllBytes(),
                            StandardCharsets.UTF_8).contains(NAMESPACE);
        } catch (IOException | InterruptedException e) {
            return false;
        }
    }

    private static int run(String... command) throws IOException, InterruptedException {
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        String out = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        int status = process.waitFor();
        if (status != 0) {
            throw new IOException(String.join(" ", command) + ": " + status + " " + out.strip());
        }
        return status;
    }

    private static void runQuietly(String... command) {
        try {
            new ProcessBuilder(command).redirectErrorStream(true).start().waitFor();
        } catch (IOException | InterruptedException e) {
            // nothing to remove
        }
    }

    /** Writes zeros flat out, and the markers, with a send buffer of {@code sendBuffer} (0: the OS's); @return when each marker's write began. */
    static long[] send(InetSocketAddress to, int sendBuffer) throws IOException {
        long[] marked = new long[MARKERS];
        byte[] zeros = new byte[16 * 1024];
        byte[] marker = new byte[64];
        for (int i = 0; i < marker.length; i++) {
            marker[i] = (byte) (i + 1);
        }
        try (Socket socket = new Socket()) {
            if (sendBuffer > 0) {
                socket.setSendBufferSize(sendBuffer);
            }
            socket.connect(to, 5000);
            OutputStream out = socket.getOutputStream();
            long start = System.nanoTime();
            int next = 0;
            long end = start + SATURATE_NS + MARKERS * EVERY_NS;
            while (System.nanoTime() - end < 0) {
                if (next < MARKERS && System.nanoTime() - (start + SATURATE_NS + next * EVERY_NS) >= 0) {
                    marked[next++] = System.nanoTime();
                    out.write(marker);
                }
                out.write(zeros);
            }
        }
        return marked;
    }

    /** Accepts one connection and notes when each marker's first byte arrives. */
    private static final class Receiver implements AutoCloseable {
        private final ServerSocket server;
        private final List<Long> arrivals = new ArrayList<>();
        private final Thread thread;

        Receiver(InetAddress address) throws IOException {
            server = new ServerSocket();
            server.bind(new InetSocketAddress(address, 0));
            thread = new Thread(this::receive, "queue-wait receiver");
            thread.setDaemon(true);
            thread.start();
        }

        int port() {
            return server.getLocalPort();
        }

        private void receive() {
            try (Socket socket = server.accept(); InputStream in = socket.getInputStream()) {
                byte[] buffer = new byte[64 * 1024];
                int inMarker = 0;
                int read;
                while ((read = in.read(buffer)) >= 0) {
                    long now = System.nanoTime();
                    for (int i = 0; i < read; i++) {
                        if (inMarker > 0) {
                            inMarker = inMarker == 64 ? 0 : inMarker + 1;
                        } else if (buffer[i] == 1) {
                            synchronized (arrivals) {
                                arrivals.add(now);
                            }
                            inMarker = 2;
                        }
                    }
                }
            } catch (IOException e) {
                // the sender is done
            }
        }

        /** The waits of the markers written at {@code marked}, once the stream has ended. */
        long[] waits(long[] marked) throws InterruptedException {
            thread.join(TimeUnit.SECONDS.toMillis(60));
            long[] waits = new long[marked.length];
            synchronized (arrivals) {
                for (int i = 0; i < marked.length; i++) {
                    waits[i] = i < arrivals.size() ? arrivals.get(i) - marked[i] : -1;
                }
            }
            return waits;
        }

        @Override
        public void close() throws IOException {
            server.close();
        }
    }
}
