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
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.usarsim.wss.shaping.Bitrate;

/**
 * Issue 27: how long a 64-byte message waits behind a saturating stream, through a shaped WSS
 * pair and through Linux's tbf at the same rate, side by side. A sender writes zeros flat out;
 * after {@link #SATURATE_NS} it writes a 64-byte marker (bytes 1 to 64) every
 * {@link #EVERY_NS}, {@link #MARKERS} times, still writing zeros between them; the receiver
 * notes when each marker's first byte arrives. The wait is from the marker's write call to its
 * arrival, on one clock (System.nanoTime is CLOCK_MONOTONIC, the same for every process). The
 * sender's own kernel's part of it (what it held not yet sent, sampled by ss) is shown beside.
 *
 * <p>Four paths: the WSS with both robots on loopback (64 KiB segments); tbf on the namespace's own
 * loopback (sender and receiver one JVM there); the WSS with the
 * sending robot across a veth pair (a JVM in a network namespace, {@code wssq-bench}, addresses
 * 10.213.27.1 and .2; the WSS listens on .1); tbf on that veth, its sender the same. The veth
 * needs root, {@code ip} and {@code tc}, and is removed after each run. The WSS runs use
 * {@code wss.force.up=A:B:RATE:2}; {@code -Dwss.bench.properties="wss.shaping.queueMs=100"}
 * sets another queue. The sender's settings (issue 36, item 17): {@code -Dwss.bench.sndbufs=0,65536}
 * the send buffers to measure, one table each (0: the OS's; these two by default);
 * {@code -Dwss.bench.notsentLowat=16384} the namespace's {@code net.ipv4.tcp_notsent_lowat}
 * (never the host's; the veth columns only, as with {@code -Dwss.bench.vethOnly=true}).
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
    /** The namespace's net.ipv4.tcp_notsent_lowat, or null for the kernel's default (no limit). */
    private static final String NOT_SENT_LOWAT = System.getProperty("wss.bench.notsentLowat");
    /** Only the veth's columns: the loopback WSS's sender is on the host, where the namespace's sysctl does not reach. */
    private static final boolean VETH_ONLY = Boolean.getBoolean("wss.bench.vethOnly") || NOT_SENT_LOWAT != null;

    private QueueWait() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length == 4 && args[0].equals("sender")) {
            printMarks(send(new InetSocketAddress(args[1], Integer.parseInt(args[2])), Integer.parseInt(args[3])));
            return;
        }
        if (args.length == 4 && args[0].equals("robot")) {
            try (ControlClient robotA = new ControlClient(args[1], Integer.parseInt(args[2]), "A", 1)) {
                printMarks(send(new InetSocketAddress(args[1], robotA.dns("B")), Integer.parseInt(args[3])));
            }
            return;
        }
        if (args.length == 3 && args[0].equals("loopback")) {
            try (Receiver receiver = new Receiver(InetAddress.getLoopbackAddress())) {
                Mark[] marked = send(new InetSocketAddress(InetAddress.getLoopbackAddress(), receiver.port()), Integer.parseInt(args[2]));
                for (Wait wait : receiver.waits(marked, Long.parseLong(args[1]))) {
                    System.out.println("WAIT " + wait.nanos() + " " + wait.sendersOwnNanos());
                }
            }
            return;
        }
        List<String> rates = args.length == 0 ? List.of("1M", "6M", "24M") : List.of(args);
        boolean veth = vethPossible();
        for (String sendBuffer : System.getProperty("wss.bench.sndbufs", "0,65536").split(",")) {
            table(rates, veth, Integer.parseInt(sendBuffer.strip()));
        }
        System.exit(0);
    }

    private static void printMarks(Mark[] marked) {
        for (Mark mark : marked) {
            if (mark != null) {
                System.out.println("MARK " + mark.nanos() + " " + mark.notSent());
            }
        }
    }

    /**
     * A marker's wait from its write call to its arrival, and the part of it its sender's own
     * kernel is answerable for: what it held not yet sent ahead of the marker, at the rate.
     * The rest is the path's: the WSS's queue and sockets (the WSS acknowledges what it takes at
     * once), or tbf's queue and what is in flight.
     */
    record Wait(long nanos, long sendersOwnNanos) {
        boolean arrived() {
            return nanos >= 0;
        }

        long pathNanos() {
            return Math.max(0, nanos - sendersOwnNanos);
        }
    }

    /**
     * One table: each rate through the WSS with both robots on loopback, through the WSS with the
     * sending robot across a veth (as tbf's sender), and through tbf on that veth; the sender's
     * send buffer {@code sendBuffer} (0: the OS's).
     */
    private static void table(List<String> rates, boolean veth, int sendBuffer) throws Exception {
        System.out.printf("%n## Queue: a 64-byte message behind a saturating stream (%d markers, 2 s apart, after 4 s; the sender's"
                + " send buffer %s; its congestion control %s; load average %s)%n%n", MARKERS,
                (sendBuffer == 0 ? "the OS's" : sendBuffer + " bytes")
                        + (NOT_SENT_LOWAT == null ? "" : ", its namespace's tcp_notsent_lowat " + NOT_SENT_LOWAT),
                Files.readString(Path.of("/proc/sys/net/ipv4/tcp_congestion_control")).strip(),
                Files.readString(Path.of("/proc/loadavg")).strip());
        System.out.println("Each wait in seconds, and in brackets the part the sender's own kernel held ahead of the marker"
                + " (not yet sent, at the rate); WSS: delay 2 ms, "
                + System.getProperty("wss.bench.properties", "the default queue").strip() + "; tbf: latency 100ms.");
        System.out.println();
        System.out.println("| rate | WSS, robots on loopback | tbf on a loopback (a namespace's) | WSS / tbf on loopback (medians)"
                + " | WSS, sender across a veth | tbf on the veth | WSS across the veth / tbf (medians)"
                + " | WSS across the veth: the wait less the sender's own part (median), s |");
        System.out.println("|---|---|---|---|---|---|---|---|");
        for (String rate : rates) {
            long bits = Bitrate.parse(rate);
            Wait[] loopback = VETH_ONLY ? new Wait[0] : throughWss(rate, sendBuffer);
            Wait[] tbfLoopback = veth && !VETH_ONLY ? throughTbfOnLoopback(rate, sendBuffer) : new Wait[0];
            Wait[] acrossVeth = veth ? throughWssAcrossVeth(rate, sendBuffer) : null;
            Wait[] viaTbf = veth ? throughTbf(rate, sendBuffer) : null;
            System.out.printf(Locale.ROOT, "| %s | %s | %s | %s | %s | %s | %s | %s |%n", Bitrate.format(bits), seconds(loopback),
                    veth ? seconds(tbfLoopback) : "(no tbf here)", veth ? ratio(loopback, tbfLoopback) : "",
                    veth ? seconds(acrossVeth) : "(no veth here)", veth ? seconds(viaTbf) : "(no tbf here)",
                    veth ? ratio(acrossVeth, viaTbf) : "", veth && Arrays.stream(acrossVeth).allMatch(Wait::arrived)
                            ? String.format(Locale.ROOT, "%.3f", median(acrossVeth, Wait::pathNanos) / 1e9) : "");
        }
    }

    private static String seconds(Wait[] waits) {
        StringBuilder text = new StringBuilder();
        for (Wait wait : waits) {
            text.append(text.length() == 0 ? "" : ", ").append(wait.nanos() == -2 ? "not written (the sender's last write ended after its time)"
                    : !wait.arrived() ? "none within 60 s of the end"
                    : String.format(Locale.ROOT, "%.3f (%.3f)", wait.nanos() / 1e9, wait.sendersOwnNanos() / 1e9));
        }
        return text.toString();
    }

    /** The ratio of the medians of two columns' waits, if every marker of both arrived. */
    private static String ratio(Wait[] wss, Wait[] tbf) {
        if (wss.length == 0 || tbf.length == 0 || !Arrays.stream(wss).allMatch(Wait::arrived)
                || !Arrays.stream(tbf).allMatch(Wait::arrived)) {
            return "";
        }
        return String.format(Locale.ROOT, "**%.2f**", (double) median(wss, Wait::nanos) / median(tbf, Wait::nanos));
    }

    private static long median(Wait[] waits, java.util.function.ToLongFunction<Wait> part) {
        long[] sorted = Arrays.stream(waits).mapToLong(part).sorted().toArray();
        return sorted[sorted.length / 2];
    }

    /** Through a WSS pinned to {@code rate}, both robots on loopback: the sender is a thread here. */
    private static Wait[] throughWss(String rate, int sendBuffer) throws Exception {
        try (WssProcess wss = WssProcess.start("wss.shaping=on", "wss.force.up=A:B:" + rate + ":2");
                Receiver receiver = new Receiver(InetAddress.getLoopbackAddress());
                ControlClient robotB = new ControlClient(wss.controlPort, "B", receiver.port());
                ControlClient robotA = new ControlClient(wss.controlPort, "A", 1)) {
            int port = robotA.dns("B");
            Mark[] marked = send(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), sendBuffer);
            return receiver.waits(marked, Bitrate.parse(rate));
        }
    }

    /**
     * Through a WSS pinned to {@code rate} listening on the veth's address: robot A (its control
     * connection and its stream) is a JVM in the namespace, as tbf's sender is, so both senders'
     * kernels see the same path (1,500-byte frames); robot B receives here.
     */
    private static Wait[] throughWssAcrossVeth(String rate, int sendBuffer) throws Exception {
        try (Veth path = Veth.create();
                WssProcess wss = WssProcess.start("wss.shaping=on", "wss.force.up=A:B:" + rate + ":2", "wss.bindAddress=" + HOST);
                Receiver receiver = new Receiver(InetAddress.getByName(HOST));
                ControlClient robotB = new ControlClient(HOST, wss.controlPort, "B", receiver.port())) {
            return receiver.waits(inNamespace("robot", HOST, String.valueOf(wss.controlPort), String.valueOf(sendBuffer)),
                    Bitrate.parse(rate));
        }
    }

    /** Through tbf at {@code rate} on the veth: the sender is a JVM in the namespace. */
    private static Wait[] throughTbf(String rate, int sendBuffer) throws Exception {
        long bits = Bitrate.parse(rate);
        try (Veth path = Veth.create(); Receiver receiver = new Receiver(InetAddress.getByName(HOST))) {
            long burst = Math.max(1600, bits / 8 / 100); // 10 ms at the rate, a frame at least
            run("ip", "netns", "exec", NAMESPACE, "tc", "qdisc", "add", "dev", "wssq1", "root", "tbf", "rate", bits + "bit",
                    "burst", String.valueOf(burst), "latency", "100ms");
            return receiver.waits(inNamespace("sender", HOST, String.valueOf(receiver.port()), String.valueOf(sendBuffer)), bits);
        }
    }

    /**
     * Through tbf at {@code rate} on the namespace's own loopback: sender and receiver are one JVM
     * in the namespace, on 127.0.0.1, so the sender's kernel sees loopback (64 KiB segments) as
     * the WSS's loopback robots do. The burst holds one such segment.
     */
    private static Wait[] throughTbfOnLoopback(String rate, int sendBuffer) throws Exception {
        long bits = Bitrate.parse(rate);
        try (Veth path = Veth.create()) {
            long burst = Math.max(70_000, bits / 8 / 100); // 10 ms at the rate, a loopback segment at least
            run("ip", "netns", "exec", NAMESPACE, "tc", "qdisc", "add", "dev", "lo", "root", "tbf", "rate", bits + "bit",
                    "burst", String.valueOf(burst), "latency", "100ms");
            List<Wait> waits = new ArrayList<>();
            for (String line : inNamespaceLines("loopback", String.valueOf(bits), String.valueOf(sendBuffer))) {
                if (line.startsWith("WAIT ")) {
                    String[] fields = line.split(" ");
                    waits.add(new Wait(Long.parseLong(fields[1]), Long.parseLong(fields[2])));
                }
            }
            return waits.toArray(new Wait[0]);
        }
    }

    /** Runs this class in the namespace with {@code args}; @return the marks it printed. */
    private static Mark[] inNamespace(String... args) throws IOException, InterruptedException {
        List<Mark> marked = new ArrayList<>();
        for (String line : inNamespaceLines(args)) {
            if (line.startsWith("MARK ")) {
                String[] fields = line.split(" ");
                marked.add(new Mark(Long.parseLong(fields[1]), Long.parseLong(fields[2])));
            }
        }
        return marked.toArray(new Mark[MARKERS]);
    }

    /** Runs this class in the namespace with {@code args}; @return its MARK and WAIT lines (the others are printed). */
    private static List<String> inNamespaceLines(String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of("ip", "netns", "exec", NAMESPACE,
                Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp", System.getProperty("java.class.path"),
                QueueWait.class.getName()));
        command.addAll(List.of(args));
        Process sender = new ProcessBuilder(command).redirectErrorStream(true).start();
        List<String> lines = new ArrayList<>();
        try (BufferedReader out = new BufferedReader(new InputStreamReader(sender.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = out.readLine()) != null) {
                if (line.startsWith("MARK ") || line.startsWith("WAIT ")) {
                    lines.add(line);
                } else {
                    System.out.println("sender: " + line);
                }
            }
        }
        sender.waitFor(90, TimeUnit.SECONDS);
        return lines;
    }

    /** A veth pair of the benchmark's own, one end in its namespace; closing removes both. */
    private static final class Veth implements AutoCloseable {
        static Veth create() throws IOException, InterruptedException {
            Veth veth = new Veth();
            try {
                run("ip", "netns", "add", NAMESPACE);
                run("ip", "link", "add", "wssq0", "type", "veth", "peer", "name", "wssq1");
                run("ip", "link", "set", "wssq1", "netns", NAMESPACE);
                run("ip", "addr", "add", HOST + "/30", "dev", "wssq0");
                run("ip", "link", "set", "wssq0", "up");
                run("ip", "netns", "exec", NAMESPACE, "ip", "addr", "add", PEER + "/30", "dev", "wssq1");
                run("ip", "netns", "exec", NAMESPACE, "ip", "link", "set", "wssq1", "up");
                run("ip", "netns", "exec", NAMESPACE, "ip", "link", "set", "lo", "up");
                if (NOT_SENT_LOWAT != null) {
                    run("ip", "netns", "exec", NAMESPACE, "sysctl", "-q", "-w", "net.ipv4.tcp_notsent_lowat=" + NOT_SENT_LOWAT);
                }
                return veth;
            } catch (IOException | InterruptedException | RuntimeException e) {
                veth.close();
                throw e;
            }
        }

        @Override
        public void close() {
            runQuietly("ip", "netns", "del", NAMESPACE); // takes wssq1, and wssq0 with it
            runQuietly("ip", "link", "del", "wssq0");
        }
    }

    /** Whether the veth and tbf can be set up here: root, ip and tc, and no namespace of that name already (someone else's). */
    private static boolean vethPossible() {
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

    /**
     * One marker as its sender wrote it: when its write began, and how many bytes the sender's
     * own kernel held not yet sent just before (ss's {@code notsent}: they go ahead of it
     * whatever the path).
     */
    record Mark(long nanos, long notSent) {
    }

    /** Writes zeros flat out, and the markers, with a send buffer of {@code sendBuffer} (0: the OS's). */
    static Mark[] send(InetSocketAddress to, int sendBuffer) throws IOException {
        Mark[] marked = new Mark[MARKERS];
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
            NotSentSampler notSent = new NotSentSampler(socket.getLocalPort());
            OutputStream out = socket.getOutputStream();
            long start = System.nanoTime();
            int next = 0;
            long end = start + SATURATE_NS + MARKERS * EVERY_NS;
            while (System.nanoTime() - end < 0) {
                if (next < MARKERS && System.nanoTime() - (start + SATURATE_NS + next * EVERY_NS) >= 0) {
                    marked[next++] = new Mark(System.nanoTime(), notSent.last());
                    out.write(marker);
                }
                out.write(zeros);
            }
            notSent.stop();
        }
        return marked;
    }

    /**
     * What the kernel holds not yet sent of the connection from a local port (ss's
     * {@code notsent}), sampled every {@link #SAMPLE_MS} on a thread of its own so that the
     * sender never waits for ss (a sender that waits lets the path drain before its marker).
     */
    private static final class NotSentSampler {
        static final long SAMPLE_MS = 100;
        private static final Pattern NOT_SENT = Pattern.compile("notsent:(\\d+)");
        private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(runnable -> {
            Thread thread = new Thread(runnable, "notsent sampler");
            thread.setDaemon(true);
            return thread;
        });
        private volatile long last;

        NotSentSampler(int port) {
            timer.scheduleWithFixedDelay(() -> last = sample(port), 0, SAMPLE_MS, TimeUnit.MILLISECONDS);
        }

        /** The last sample: at most {@link #SAMPLE_MS} and an ss run old. */
        long last() {
            return last;
        }

        void stop() {
            timer.shutdownNow();
        }

        private long sample(int port) {
            try {
                Process ss = new ProcessBuilder("ss", "-tiH", "state", "established", "( sport = :" + port + " )")
                        .redirectErrorStream(true).start();
                Matcher matcher = NOT_SENT.matcher(new String(ss.getInputStream().readAllBytes(), StandardCharsets.UTF_8));
                ss.waitFor();
                return matcher.find() ? Long.parseLong(matcher.group(1)) : 0; // ss leaves out a notsent of 0
            } catch (IOException e) {
                return last;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return last;
            }
        }
    }

    /** Accepts one connection and notes when each marker's first byte arrives. */
    private static final class Receiver implements AutoCloseable {
        private final ServerSocket server;
        private final List<Long> arrivals = new ArrayList<>();
        private final Thread thread;
        private long received;
        private long first;
        private long last;

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
                    first = received == 0 ? now : first;
                    received += read;
                    last = now;
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

        /** The waits of the markers written as {@code marked}, once the stream has ended. */
        Wait[] waits(Mark[] marked, long bitsPerSecond) throws InterruptedException {
            thread.join(TimeUnit.SECONDS.toMillis(60));
            if (last > first) { // what the sender's settings cost the stream: its rate from its first byte to its last
                System.out.printf(Locale.ROOT, "received %d bytes in %.3f s: %.3f Mbit/s%n", received, (last - first) / 1e9,
                        received * 8e3 / (last - first));
            }
            Wait[] waits = new Wait[marked.length];
            synchronized (arrivals) {
                for (int i = 0; i < marked.length; i++) {
                    waits[i] = marked[i] == null ? new Wait(-2, 0) // the stream ended before its time to be written
                            : new Wait(i < arrivals.size() ? arrivals.get(i) - marked[i].nanos() : -1,
                                    marked[i].notSent() * 8_000_000_000L / bitsPerSecond);
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
