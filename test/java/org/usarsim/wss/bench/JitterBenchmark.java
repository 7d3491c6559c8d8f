package org.usarsim.wss.bench;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.util.Arrays;
import java.util.Locale;
import java.util.function.DoubleUnaryOperator;

/**
 * The jitter (issue 35, docs/shaping.md "Jitter") measured through a real server: 10,000
 * datagrams through a fixed UDP port with a delay of 50 ms and a jitter of 20 ms (normal, then
 * uniform; {@code wss.shaping.reorder=true}, so that each datagram keeps its own draw), their
 * one-way delays against the configured distribution (the Kolmogorov-Smirnov distance D, and D
 * once the measured mean offset, the machine's own latency, is taken away); and a TCP stream
 * through a fixed TCP port with the same jitter at 8 Mbit/s: in order (every 8-byte sequence
 * number in turn) and at its rate. {@code --datagrams N --seconds S}; docs/performance.md has the
 * command and the figures.
 */
public final class JitterBenchmark {

    private static final InetAddress LOCAL = InetAddress.getLoopbackAddress();
    private static final int DELAY_MS = 50;
    private static final int JITTER_MS = 20;
    private static final int PAYLOAD = 100;
    private static final long RATE = 54_000_000;
    private static final long TCP_RATE = 8_000_000;

    public static void main(String[] args) throws Exception {
        int datagrams = 10_000;
        int seconds = 10;
        String only = "";
        for (int i = 0; i < args.length; i += 2) {
            switch (args[i]) {
                case "--datagrams" -> datagrams = Integer.parseInt(args[i + 1]);
                case "--seconds" -> seconds = Integer.parseInt(args[i + 1]);
                case "--only" -> only = args[i + 1];
                default -> throw new IllegalArgumentException("--datagrams N --seconds S --only udp|tcp, not " + args[i]);
            }
        }
        if (only.isEmpty() || only.equals("udp")) {
            System.out.printf(Locale.ROOT, "%n## %,d datagrams of %d bytes through a fixed UDP port, delay %d ms, jitter %d ms, reorder on%n%n",
                    datagrams, PAYLOAD, DELAY_MS, JITTER_MS);
            System.out.println("| distribution | mean ms (configured) | sd ms (configured) | reordered arrivals | D | D, mean offset removed"
                    + " | D against the configured + the machine's own delay (the jitter-0 row's) | critical D at 5 % (1.36/sqrt(n)) |");
            System.out.println("|---|---|---|---|---|---|---|---|");
            double[] own = udp("none", datagrams, null); // the machine's own latency: the delay alone
            udp("normal", datagrams, own);
            udp("uniform", datagrams, own);
        }
        if (only.isEmpty() || only.equals("tcp")) {
            tcp(seconds);
        }
    }

    /** The configured delay's CDF in ms: max(0, delay + jitter x Z) plus the datagram's airtime. */
    private static DoubleUnaryOperator configured(String distribution) {
        double airMs = PAYLOAD * 8.0 / RATE * 1e3;
        return distribution.equals("normal")
                ? x -> x - airMs < 0 ? 0 : phi((x - airMs - DELAY_MS) / JITTER_MS)
                : x -> Math.max(0, Math.min(1, (x - airMs - (DELAY_MS - JITTER_MS)) / (2.0 * JITTER_MS)));
    }

    /** Phi on [-8, 8] in steps of 1/1024, by Simpson's rule on the density, computed once. */
    private static final double[] PHI = new double[16 * 1024 + 1];

    static {
        double h = 1.0 / 1024;
        for (int i = 1; i < PHI.length; i++) {
            double a = -8 + (i - 1) * h;
            PHI[i] = PHI[i - 1] + h / 6 * (density(a) + 4 * density(a + h / 2) + density(a + h));
        }
    }

    /** Phi(x), interpolated in the table. */
    static double phi(double x) {
        if (x <= -8) {
            return 0;
        }
        if (x >= 8) {
            return 1;
        }
        double at = (x + 8) * 1024;
        int i = (int) at;
        return PHI[i] + (at - i) * (PHI[i + 1] - PHI[i]);
    }

    private static double density(double x) {
        return Math.exp(-x * x / 2) / Math.sqrt(2 * Math.PI);
    }

    /** The Kolmogorov-Smirnov distance of the sorted sample {@code x} (shifted by {@code shift}) from {@code cdf}. */
    static double ks(double[] sorted, double shift, DoubleUnaryOperator cdf) {
        int n = sorted.length;
        double d = 0;
        for (int i = 0; i < n; i++) {
            double f = cdf.applyAsDouble(sorted[i] - shift);
            d = Math.max(d, Math.max(Math.abs((i + 1.0) / n - f), Math.abs((double) i / n - f)));
        }
        return d;
    }

    /** The configured distribution's mean, by the midpoint rule over its CDF's quantiles (x from 0 to delay + 5 jitters). */
    private static double mean(DoubleUnaryOperator cdf) {
        double sum = 0;
        double step = 0.01;
        for (double x = 0; x < DELAY_MS + 5 * JITTER_MS; x += step) {
            sum += (1 - cdf.applyAsDouble(x + step / 2)) * step; // E[X] = integral of the survival function, X >= 0
        }
        return sum;
    }

    /**
     * The configured CDF with the machine's own delay added: the mean of {@code cdf} shifted by
     * each of 200 quantiles of {@code own}'s excess over the delay (the jitter-0 run's).
     */
    private static DoubleUnaryOperator withOwn(DoubleUnaryOperator cdf, double[] own) {
        double[] excess = new double[200];
        for (int i = 0; i < excess.length; i++) {
            excess[i] = own[(int) ((i + 0.5) / excess.length * own.length)] - (DELAY_MS + PAYLOAD * 8.0 / RATE * 1e3);
        }
        return x -> {
            double sum = 0;
            for (double e : excess) {
                sum += cdf.applyAsDouble(x - e);
            }
            return sum / excess.length;
        };
    }

    /** @return the sorted delays measured, in ms */
    private static double[] udp(String distribution, int count, double[] own) throws Exception {
        try (DatagramSocket sink = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
            sink.setReceiveBufferSize(8 << 20);
            int fixed = freeUdp();
            try (WssProcess wss = WssProcess.start("wss.robot.Source=", "wss.robot.Sink=", "wss.shaping=on", "wss.shaping.rates=0:54M",
                    "wss.shaping.loss=", "wss.shaping.delayMs=" + DELAY_MS, "wss.shaping.jitter=" + (distribution.equals("none") ? 0 : JITTER_MS),
                    "wss.shaping.jitterDistribution=" + (distribution.equals("none") ? "uniform" : distribution), "wss.shaping.reorder=true",
                    "wss.fixed=udp Source->Sink:" + sink.getLocalPort() + "@" + fixed);
                    DatagramSocket source = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
                long[] sentAt = new long[count];
                double[] delays = new double[count];
                int[] received = {0};
                int[] reordered = {0};
                Thread receiving = new Thread(() -> {
                    DatagramPacket packet = new DatagramPacket(new byte[PAYLOAD * 2], PAYLOAD * 2);
                    int last = -1;
                    try {
                        sink.setSoTimeout(3000);
                        while (received[0] < count) {
                            sink.receive(packet);
                            long now = System.nanoTime();
                            int sequence = ByteBuffer.wrap(packet.getData(), 0, 4).getInt();
                            synchronized (sentAt) {
                                delays[received[0]++] = (now - sentAt[sequence]) / 1e6;
                            }
                            reordered[0] += sequence < last ? 1 : 0;
                            last = Math.max(last, sequence);
                        }
                    } catch (IOException done) {
                        // three seconds of silence: all that comes has come
                    }
                }, "jitter-sink");
                receiving.start();
                byte[] data = new byte[PAYLOAD];
                DatagramPacket packet = new DatagramPacket(data, PAYLOAD, LOCAL, fixed);
                long start = System.nanoTime();
                for (int i = 0; i < count; i++) {
                    long due = start + i * 500_000L; // 2,000 a second, parked rather than spun: the server needs the cores
                    while (System.nanoTime() - due < 0) {
                        java.util.concurrent.locks.LockSupport.parkNanos(due - System.nanoTime());
                    }
                    ByteBuffer.wrap(data).putInt(0, i);
                    synchronized (sentAt) {
                        sentAt[i] = System.nanoTime();
                    }
                    source.send(packet);
                }
                receiving.join(60_000);
                int n = received[0];
                double[] sorted = Arrays.copyOf(delays, n);
                Arrays.sort(sorted);
                DoubleUnaryOperator cdf = configured(distribution);
                double measuredMean = Arrays.stream(sorted).average().orElse(Double.NaN);
                double sd = Math.sqrt(Arrays.stream(sorted).map(x -> (x - measuredMean) * (x - measuredMean)).sum() / n);
                if (distribution.equals("none")) {
                    System.out.printf(Locale.ROOT, "| none (jitter 0: the machine's own) | %.2f (%.2f) | %.2f (0) | %d of %d | - | - | - | - |%n",
                            measuredMean, DELAY_MS + PAYLOAD * 8.0 / RATE * 1e3, sd, reordered[0], n);
                    return sorted;
                }
                double configuredMean = mean(cdf);
                double configuredSd = distribution.equals("normal") ? JITTER_MS : JITTER_MS / Math.sqrt(3);
                System.out.printf(Locale.ROOT, "| %s | %.2f (%.2f) | %.2f (%.2f) | %d of %d | %.4f | %.4f (offset %.2f ms) | %.4f | %.4f |%n",
                        distribution, measuredMean, configuredMean, sd, configuredSd, reordered[0], n, ks(sorted, 0, cdf),
                        ks(sorted, measuredMean - configuredMean, cdf), measuredMean - configuredMean, ks(sorted, 0, withOwn(cdf, own)),
                        1.36 / Math.sqrt(n));
                return sorted;
            }
        }
    }

    private static void tcp(int seconds) throws Exception {
        try (ServerSocket sinkListens = new ServerSocket(0, 1, LOCAL)) {
            int fixed = freeTcp();
            try (WssProcess wss = WssProcess.start("wss.robot.Source=", "wss.robot.Sink=", "wss.shaping=on",
                    "wss.shaping.rates=0:" + TCP_RATE / 1_000_000 + "M", "wss.shaping.delayMs=" + DELAY_MS, "wss.shaping.jitter=" + JITTER_MS,
                    "wss.shaping.jitterDistribution=normal", "wss.fixed=Source->Sink:" + sinkListens.getLocalPort() + "@" + fixed);
                    Socket source = new Socket(LOCAL, fixed); Socket sink = sinkListens.accept()) {
                long[] outOfOrder = {0};
                long[] longs = {0};
                long[] firstAndLast = {0, 0};
                Thread reading = new Thread(() -> {
                    try (InputStream in = sink.getInputStream()) {
                        DataInputStream data = new DataInputStream(new java.io.BufferedInputStream(in, 1 << 16));
                        long expected = 0;
                        while (true) {
                            long sequence = data.readLong();
                            long now = System.nanoTime();
                            if (expected == 0) {
                                firstAndLast[0] = now;
                            }
                            firstAndLast[1] = now;
                            outOfOrder[0] += sequence != expected ? 1 : 0;
                            expected = sequence + 1;
                            longs[0]++;
                        }
                    } catch (IOException end) {
                        // the stream ended
                    }
                }, "jitter-tcp-sink");
                reading.start();
                long end = System.nanoTime() + seconds * 1_000_000_000L;
                try (OutputStream out = source.getOutputStream()) {
                    DataOutputStream data = new DataOutputStream(new java.io.BufferedOutputStream(out, 1 << 14));
                    long sequence = 0;
                    while (System.nanoTime() - end < 0) {
                        for (int i = 0; i < 1024; i++) {
                            data.writeLong(sequence++);
                        }
                    }
                    data.flush();
                    source.shutdownOutput();
                    reading.join(60_000);
                    double secondsTaken = (firstAndLast[1] - firstAndLast[0]) / 1e9;
                    double bitsPerSecond = (longs[0] - 1) * 64.0 / secondsTaken;
                    System.out.printf(Locale.ROOT, "%n## A TCP stream through a fixed TCP port at %d Mbit/s, delay %d ms, jitter %d ms normal, %d s%n%n",
                            TCP_RATE / 1_000_000, DELAY_MS, JITTER_MS, seconds);
                    System.out.println("| sent (8-byte numbers) | received | out of order | Mbit/s, first to last byte | of the rate |");
                    System.out.println("|---|---|---|---|---|");
                    System.out.printf(Locale.ROOT, "| %,d | %,d | %d | %.3f | %.4f |%n", sequence, longs[0], outOfOrder[0], bitsPerSecond / 1e6,
                            bitsPerSecond / TCP_RATE);
                }
            }
        }
    }

    private static int freeUdp() throws IOException {
        try (DatagramSocket socket = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
            return socket.getLocalPort();
        }
    }

    private static int freeTcp() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, LOCAL)) {
            return socket.getLocalPort();
        }
    }
}
