package org.usarsim.wss.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.usarsim.wss.shaping.Bitrate;

/**
 * Measures links shaped like radio (issue 16, docs/shaping.md) through a real WSS, a separate
 * headless JVM on 127.0.0.1 as {@link RelayBenchmark} starts it, and prints what it measured
 * against what the links were pinned to, as ratios. Nothing here is asserted. See
 * docs/performance.md, "Shaping".
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.ShapingBenchmark [--seconds 10] [--only NAME]
 *     [--bulk-mb 100] [--relay-rate 24M] [--near-rate 24M] [--far-rate 6M] [--cost-rate 8M] [--repeats 7] [--raise-hold 3] [--raise-from 1]
 * </pre>
 * NAME is one of accuracy, latency, airtime, raise, relay, cost, bulk.
 */
public final class ShapingBenchmark {

    private static final int CHUNK = 64 * 1024;
    private static final long SECOND = 1_000_000_000L;
    /** The rates of the accuracy section, from 512 kbit/s to 54 Mbit/s. */
    private static final String[] ACCURACY_RATES = {"512k", "2M", "6M", "11M", "24M", "54M"};
    private static final int[] DELAYS_MS = {0, 5, 50, 200};

    private final int seconds;
    private final long bulkBytes;
    private final String relayRate;
    private final String nearRate;
    private final String costRate;
    private final String farRate;
    private final int repeats;
    private final long raiseHold;
    private final String raiseFrom;

    private ShapingBenchmark(int seconds, long bulkBytes, String relayRate, String nearRate, String farRate, String costRate, int repeats,
            long raiseHold, String raiseFrom) {
        this.raiseFrom = raiseFrom;
        this.repeats = repeats;
        this.raiseHold = raiseHold;
        this.farRate = farRate;
        this.seconds = seconds;
        this.bulkBytes = bulkBytes;
        this.relayRate = relayRate;
        this.nearRate = nearRate;
        this.costRate = costRate;
    }

    public static void main(String[] args) throws Exception {
        int seconds = 10;
        long bulkMb = 100;
        String only = null;
        String relayRate = "24M";
        String nearRate = "24M";
        String costRate = "8M";
        String farRate = null;
        int repeats = 7;
        long raiseHold = 3;
        String raiseFrom = "1";
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--seconds" -> seconds = Integer.parseInt(args[++i]);
                case "--only" -> only = args[++i];
                case "--bulk-mb" -> bulkMb = Long.parseLong(args[++i]);
                case "--relay-rate" -> relayRate = args[++i];
                case "--near-rate" -> nearRate = args[++i];
                case "--far-rate" -> farRate = args[++i];
                case "--cost-rate" -> costRate = args[++i];
                case "--repeats" -> repeats = Integer.parseInt(args[++i]);
                case "--raise-hold" -> raiseHold = Long.parseLong(args[++i]);
                case "--raise-from" -> raiseFrom = args[++i];
                default -> throw new IllegalArgumentException("unknown argument " + args[i]);
            }
        }
        if (only != null && !List.of("accuracy", "latency", "airtime", "raise", "relay", "cost", "bulk").contains(only)) {
            throw new IllegalArgumentException("--only takes accuracy, latency, airtime, raise, relay, cost or bulk, not " + only);
        }
        ShapingBenchmark benchmark = new ShapingBenchmark(seconds, bulkMb * 1_000_000, relayRate, nearRate, farRate, costRate, repeats, raiseHold, raiseFrom);
        System.out.printf("WSS shaping benchmark: %d cores, %s, %s, load average %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name") + " " + System.getProperty("java.version"), java.time.LocalDateTime.now(), load());
        if (only == null || only.equals("accuracy")) {
            benchmark.accuracy();
        }
        if (only == null || only.equals("latency")) {
            benchmark.latency();
        }
        if (only == null || only.equals("airtime")) {
            benchmark.airtime();
        }
        if (only == null || only.equals("raise")) {
            benchmark.raise();
        }
        if (only == null || only.equals("relay")) {
            benchmark.relay();
        }
        if (only == null || only.equals("cost")) {
            benchmark.cost();
        }
        if (only == null || only.equals("bulk")) {
            benchmark.bulk();
        }
        System.out.printf("%nDone, load average %s%n", load());
        System.exit(0);
    }

    // ---- 1. accuracy: one bulk stream at each pinned rate ----

    /**
     * One stream per rate, each between its own two robots pinned to it (wss.force.up, delay 2 ms),
     * one after the other; the sender writes as fast as the WSS takes it. Goodput is counted
     * where the target robot reads it: "steady" over {@code seconds} after the first second of
     * the first byte's arrival, "whole" over the first 1 + {@code seconds} from the moment the
     * sender connected (link set-up, the delay and the first grants included). Two unmeasured
     * seconds of another pair at 54 Mbit/s come first.
     */
    private void accuracy() throws Exception {
        System.out.printf("%n## Accuracy: one stream for 1 + %d s at each pinned rate (delay 2 ms, load average %s)%n%n", seconds, load());
        StringBuilder pins = new StringBuilder();
        for (int i = 0; i < ACCURACY_RATES.length; i++) {
            pins.append(i == 0 ? "" : ",").append("S").append(i).append(":T").append(i).append(':').append(ACCURACY_RATES[i]).append(":2");
        }
        try (WssProcess wss = WssProcess.start("wss.shaping=on", "wss.force.up=" + pins + ",WarmS:WarmT:54M:2")) {
            warmUp(wss);
            System.out.println("| pinned rate | steady Mbit/s (s 1 to " + (1 + seconds) + ") | steady/rate | whole Mbit/s (s 0 to " + (1 + seconds)
                    + ") | whole/rate | link thread waited for a CPU, ms/s |");
            System.out.println("|---|---|---|---|---|---|");
            for (int i = 0; i < ACCURACY_RATES.length; i++) {
                long rate = Bitrate.parse(ACCURACY_RATES[i]);
                Counter received = new Counter(true);
                try (Sink sink = new Sink(received, null); ControlClient target = new ControlClient(wss.controlPort, "T" + i, sink.port());
                        ControlClient source = new ControlClient(wss.controlPort, "S" + i, 1)) {
                    int port = source.dns("T" + i);
                    long connected = System.nanoTime();
                    Sender sender = Sender.start(port, Long.MAX_VALUE, null);
                    long first = received.awaitFirst(10 * SECOND);
                    sleepUntil(first + SECOND);
                    Map<String, Long> waits = ProcessStats.linkThreadsWaitNanos(wss.pid());
                    sleepUntil(first + (1 + seconds) * SECOND);
                    double waited = ProcessStats.waitedBetween(waits, ProcessStats.linkThreadsWaitNanos(wss.pid())) / 1e6 / seconds;
                    sleepUntil(Math.max(first, connected) + (1 + seconds) * SECOND + 100_000_000L);
                    sender.stop();
                    double steady = received.between(first + SECOND, first + (1 + seconds) * SECOND) * 8.0 / seconds;
                    double whole = received.between(connected, connected + (1 + seconds) * SECOND) * 8.0 / (1 + seconds);
                    System.out.printf(Locale.ROOT, "| %s | %.4f | **%.4f** | %.4f | %.4f | %.0f |%n", Bitrate.format(rate), steady / 1e6,
                            steady / rate, whole / 1e6, whole / rate, waited);
                }
            }
        }
    }

    /** Two unmeasured seconds of a 54 Mbit/s stream, so that the first row does not pay for the server's JIT alone. */
    private static void warmUp(WssProcess wss) throws Exception {
        try (Sink sink = new Sink(new Counter(false), null); ControlClient target = new ControlClient(wss.controlPort, "WarmT", sink.port());
                ControlClient source = new ControlClient(wss.controlPort, "WarmS", 1)) {
            Sender sender = Sender.start(source.dns("WarmT"), Long.MAX_VALUE, null);
            Thread.sleep(2000);
            sender.stop();
        }
    }

    // ---- 2. latency: 64-byte round trips at pinned delays ----

    /**
     * Round trips of a 64-byte message to an echo robot over a pair an operator pins with FORCE
     * (54 Mbit/s, the delay of the row; a new connection for each), after 5 unmeasured ones.
     * Each way costs the delay plus 64 bytes' airtime (9.5 µs at 54 Mbit/s).
     */
    private void latency() throws Exception {
        System.out.printf("%n## Latency: 64-byte round trips at pinned delays (54 Mbit/s, FORCE from 127.0.0.1, load average %s)%n%n", load());
        try (EchoServer echo = new EchoServer(64); WssProcess wss = WssProcess.start("wss.shaping=on");
                ControlClient echoRobot = new ControlClient(wss.controlPort, "Echo", echo.port());
                ControlClient pinger = new ControlClient(wss.controlPort, "Pinger", 1);
                ControlClient operator = ControlClient.operator(wss.controlPort)) {
            int port = pinger.dns("Echo");
            System.out.println("| delay ms | rounds | 2 x delay ms | min ms | median ms | p99 ms | max ms | median - 2d | p99 - 2d "
                    + "| link thread waited for a CPU, µs per round trip |");
            System.out.println("|---|---|---|---|---|---|---|---|---|---|");
            for (int delay : DELAYS_MS) {
                operator.forceUp("Pinger", "Echo", "54M", delay);
                int rounds = (int) Math.max(50, Math.min(2000, seconds * 1000L / Math.max(1, 2 * delay)));
                WaitSampler waits = WaitSampler.start(wss.pid());
                long[] rtts = RelayBenchmark.roundTrips(port, rounds, false, 5);
                double waited = waits.stop() / 1e3 / (rounds + 5);
                double twice = 2.0 * delay;
                double median = RelayBenchmark.percentile(rtts, 50) / 1e6;
                double p99 = RelayBenchmark.percentile(rtts, 99) / 1e6;
                System.out.printf(Locale.ROOT, "| %d | %d | %.0f | %.3f | %.3f | %.3f | %.3f | **+%.3f** | **+%.3f** | %.0f |%n", delay, rounds,
                        twice, Arrays.stream(rtts).min().getAsLong() / 1e6, median, p99, Arrays.stream(rtts).max().getAsLong() / 1e6,
                        median - twice, p99 - twice, waited);
            }
        }
    }

    // ---- 3. airtime: one robot sending to two peers at once ----

    /**
     * Robot A sends to B (pinned to the near rate) and C (the far rate, a quarter of the near one
     * unless given) at once, both as fast as the WSS takes them. Each link's share of A's airtime
     * is its bytes x 8 / its rate over the window (the {@code seconds} after the first second of
     * both streams). Then an operator raises A-C to the near rate, and the time until C has read
     * a quantum's worth at the raised rate more is measured from the FORCE's reply.
     */
    private void airtime() throws Exception {
        long near = Bitrate.parse(nearRate);
        long far = farRate == null ? near / 4 : Bitrate.parse(farRate);
        System.out.printf("%n## Airtime: A sends to B (%s) and C (%s) at once for 1 + %d s (delay 2 ms, load average %s)%n%n",
                Bitrate.format(near), Bitrate.format(far), seconds, load());
        Counter toB = new Counter(true);
        Counter toC = new Counter(true);
        try (WssProcess wss = WssProcess.start("wss.shaping=on", "wss.force.up=A:B:" + near + ":2,A:C:" + far + ":2");
                Sink b = new Sink(toB, null); Sink c = new Sink(toC, null);
                ControlClient robotB = new ControlClient(wss.controlPort, "B", b.port());
                ControlClient robotC = new ControlClient(wss.controlPort, "C", c.port());
                ControlClient robotA = new ControlClient(wss.controlPort, "A", 1);
                ControlClient operator = ControlClient.operator(wss.controlPort)) {
            int portB = robotA.dns("B");
            int portC = robotA.dns("C");
            Sender senderB = Sender.start(portB, Long.MAX_VALUE, null);
            Sender senderC = Sender.start(portC, Long.MAX_VALUE, null);
            long start = Math.max(toB.awaitFirst(10 * SECOND), toC.awaitFirst(10 * SECOND)) + SECOND;
            long end = start + seconds * SECOND;
            sleepUntil(start);
            Map<String, Long> waits = ProcessStats.linkThreadsWaitNanos(wss.pid());
            sleepUntil(end);
            double waited = ProcessStats.waitedBetween(waits, ProcessStats.linkThreadsWaitNanos(wss.pid())) / 1e6 / seconds;
            sleepUntil(end + 100_000_000L);
            long before = toC.total();
            long quantum = near * 2 / 1000 / 8;
            long raised = System.nanoTime();
            operator.forceUp("A", "C", nearRate, 2);
            long replied = System.nanoTime();
            long reached = toC.awaitTotal(before + quantum, 10 * SECOND);
            senderB.stop();
            senderC.stop();
            double shareB = toB.between(start, end) * 8.0 / near / seconds;
            double shareC = toC.between(start, end) * 8.0 / far / seconds;
            System.out.println("| link | pinned rate | Mbit/s | share of A's airtime | expected |");
            System.out.println("|---|---|---|---|---|");
            System.out.printf(Locale.ROOT, "| A to B | %s | %.3f | **%.1f %%** | 50 %% (%.3f Mbit/s) |%n", Bitrate.format(near),
                    toB.between(start, end) * 8.0 / seconds / 1e6, 100 * shareB, near / 2e6);
            System.out.printf(Locale.ROOT, "| A to C | %s | %.3f | **%.1f %%** | 50 %% (%.3f Mbit/s) |%n", Bitrate.format(far),
                    toC.between(start, end) * 8.0 / seconds / 1e6, 100 * shareC, far / 2e6);
            System.out.printf(Locale.ROOT, "| together | | | **%.1f %%** | 100 %% |%n", 100 * (shareB + shareC));
            System.out.printf(Locale.ROOT, "%nThe two link threads waited for a CPU %.0f ms per second (together).%n", waited);
            if (far * 100 <= near) { // a faster far link moves a quantum of the near rate by itself in a few ms
                System.out.printf(Locale.ROOT, "A-C raised to %s by FORCE: C read %d bytes more (a quantum at the raised rate) %.1f ms"
                        + " after the FORCE was sent, %.1f ms after its reply (the grant on the air, B's turn, one of its own and the"
                        + " 2 ms delay: 6 ms, and the threads' wake-ups).%n", Bitrate.format(near), quantum, (reached - raised) / 1e6,
                        (reached - replied) / 1e6);
            }
            System.out.println();
            System.out.println("The shares above are computed from the bytes the peers received.");
        }
    }

    // ---- 4. raise: a link at 1 bit/s raised to 54 Mbit/s beside one at 54 Mbit/s ----

    /** How long a recovered link's share is measured over: ten turns of each link on A's radio. */
    private static final long SHARE_WINDOW_NS = 20_000_000L;

    /**
     * Issue 27's probe, {@code repeats} times, each with robots of its own in one server: A-B
     * pinned to 1 bit/s (delay 0) and A-C to 54 Mbit/s (delay 2 ms) by FORCE, A sending to both as
     * fast as the WSS takes it; after {@code raiseHold} seconds (A-B's buffers full, its sender's TCP
     * waiting for a window) an operator raises A-B to 54 Mbit/s (delay 0). Measured from the FORCE's
     * sending and from its reply: the time until B reads its next byte, until it has read a
     * quantum's worth at 54 Mbit/s (13,500 bytes) more than the frame A-B held, and until both links
     * are back to their share (the end of the first {@link #SHARE_WINDOW_NS} over which each moved
     * at least 40 % of A's radio: 20 ms at the soonest).
     */
    private void raise() throws Exception {
        long rate = Bitrate.parse("54M");
        System.out.printf("%n## Raise: A-B at %s beside A-C at 54 Mbit/s for %d s, then A-B raised to 54 Mbit/s, %d times "
                + "(load average %s)%n%n", Bitrate.format(Bitrate.parse(raiseFrom)), raiseHold, repeats, load());
        long[] trips = new long[repeats];
        long[] fromSent = new long[repeats];
        long[] fromReply = new long[repeats];
        long[] quanta = new long[repeats];
        long[] shares = new long[repeats];
        long quantum = rate * 2 / 1000 / 8;
        try (WssProcess wss = WssProcess.start("wss.shaping=on"); ControlClient operator = ControlClient.operator(wss.controlPort)) {
            System.out.println("| run | FORCE's round trip, ms | B's next byte, ms after the FORCE was sent | after its reply "
                    + "| B's frame and a quantum more, ms after the FORCE was sent | both at their share, ms after the FORCE was sent |");
            System.out.println("|---|---|---|---|---|---|");
            for (int i = 0; i < repeats; i++) {
                Counter toB = new Counter(true);
                Counter toC = new Counter(true);
                String a = "A" + i;
                String b = "B" + i;
                String c = "C" + i;
                try (Sink sinkB = new Sink(toB, null); Sink sinkC = new Sink(toC, null);
                        ControlClient robotB = new ControlClient(wss.controlPort, b, sinkB.port());
                        ControlClient robotC = new ControlClient(wss.controlPort, c, sinkC.port());
                        ControlClient robotA = new ControlClient(wss.controlPort, a, 1)) {
                    operator.forceUp(a, b, raiseFrom, 0);
                    operator.forceUp(a, c, "54M", 2);
                    Sender senderB = Sender.start(robotA.dns(b), Long.MAX_VALUE, null);
                    Sender senderC = Sender.start(robotA.dns(c), Long.MAX_VALUE, null);
                    sleepUntil(toC.awaitFirst(10 * SECOND) + raiseHold * SECOND);
                    long sent = System.nanoTime();
                    operator.forceUp(a, b, "54M", 0);
                    long replied = System.nanoTime();
                    long before = toB.at(sent);
                    long next = toB.awaitAfter(sent, 30 * SECOND);
                    trips[i] = replied - sent;
                    fromSent[i] = next - sent;
                    fromReply[i] = next - replied;
                    quanta[i] = toB.awaitTotal(before + 1500 + quantum, 30 * SECOND) - sent;
                    shares[i] = bothAtShare(toB, toC, sent, rate / 2, 30 * SECOND) - sent;
                    senderB.stop();
                    senderC.stop();
                }
                System.out.printf(Locale.ROOT, "| %d | %.1f | %.1f | %.1f | %.1f | %.1f |%n", i + 1, trips[i] / 1e6, fromSent[i] / 1e6,
                        fromReply[i] / 1e6, quanta[i] / 1e6, shares[i] / 1e6);
            }
        }
        System.out.printf(Locale.ROOT, "| median | %.1f | **%.1f** | **%.1f** | **%.1f** | **%.1f** |%n", RelayBenchmark.percentile(trips, 50) / 1e6,
                RelayBenchmark.percentile(fromSent, 50) / 1e6, RelayBenchmark.percentile(fromReply, 50) / 1e6,
                RelayBenchmark.percentile(quanta, 50) / 1e6, RelayBenchmark.percentile(shares, 50) / 1e6);
        System.out.printf(Locale.ROOT, "| max | %.1f | %.1f | %.1f | %.1f | %.1f |%n", max(trips) / 1e6, max(fromSent) / 1e6, max(fromReply) / 1e6,
                max(quanta) / 1e6, max(shares) / 1e6);
        System.out.printf(Locale.ROOT, "%nThe logic's bound for B's next byte (ShapedFlowTest, moved clock): one quantum, 2 ms, plus a "
                + "frame's airtime at 54 Mbit/s, 0.22 ms, plus the delay, 0, from the moment the link takes the raise; a quantum "
                + "more within four quanta. A negative time after the reply: B read its byte before the operator read the reply.%n");
    }

    private static long max(long[] values) {
        return Arrays.stream(values).max().getAsLong();
    }

    /**
     * The end of the first {@link #SHARE_WINDOW_NS} after {@code fromNs} over which both links
     * moved at least 80 % of {@code share} bit/s (40 % of the radio each), in steps of 0.1 ms,
     * waiting at most {@code timeoutNs}.
     */
    private static long bothAtShare(Counter one, Counter other, long fromNs, long share, long timeoutNs)
            throws InterruptedException, IOException {
        long least = share * 8 / 10 / 8 * SHARE_WINDOW_NS / SECOND;
        long deadline = System.nanoTime() + timeoutNs;
        for (long end = fromNs + SHARE_WINDOW_NS;; end += 100_000L) {
            while (System.nanoTime() - end < 0) {
                if (System.nanoTime() - deadline > 0) {
                    throw new IOException("the links did not recover their shares");
                }
                Thread.sleep(5);
            }
            if (one.between(end - SHARE_WINDOW_NS, end) >= least && other.between(end - SHARE_WINDOW_NS, end) >= least) {
                return end;
            }
        }
    }

    // ---- 5. relay: A to R to B, R's own program relaying ----

    /**
     * A sends to R (pinned A:R), R's program writes every byte it reads to B through the WSS
     * (pinned R:B at the same rate). R's radio receives and sends, so A to B gets at most half.
     */
    private void relay() throws Exception {
        long rate = Bitrate.parse(relayRate);
        System.out.printf("%n## Relay: A to R to B, both hops pinned to %s, for 1 + %d s (delay 2 ms, load average %s)%n%n",
                Bitrate.format(rate), seconds, load());
        Counter atR = new Counter(true);
        Counter atB = new Counter(true);
        try (WssProcess wss = WssProcess.start("wss.shaping=on", "wss.force.up=A:R:" + rate + ":2,R:B:" + rate + ":2");
                Sink b = new Sink(atB, null); RelayRobot relay = new RelayRobot(atR);
                ControlClient robotB = new ControlClient(wss.controlPort, "B", b.port());
                ControlClient robotR = new ControlClient(wss.controlPort, "R", relay.port());
                ControlClient robotA = new ControlClient(wss.controlPort, "A", 1)) {
            relay.target(robotR.dns("B"));
            Sender sender = Sender.start(robotA.dns("R"), Long.MAX_VALUE, null);
            long start = atB.awaitFirst(10 * SECOND) + SECOND;
            long end = start + seconds * SECOND;
            sleepUntil(start);
            Map<String, Long> waits = ProcessStats.linkThreadsWaitNanos(wss.pid());
            sleepUntil(end);
            double waited = ProcessStats.waitedBetween(waits, ProcessStats.linkThreadsWaitNanos(wss.pid())) / 1e6 / seconds;
            sleepUntil(end + 100_000_000L);
            sender.stop();
            double ar = atR.between(start, end) * 8.0 / seconds;
            double ab = atB.between(start, end) * 8.0 / seconds;
            System.out.println("| hop | Mbit/s | of the pinned rate | expected |");
            System.out.println("|---|---|---|---|");
            System.out.printf(Locale.ROOT, "| A to R (read by R) | %.3f | %.3f | 0.5 |%n", ar / 1e6, ar / rate);
            System.out.printf(Locale.ROOT, "| A to B (read by B) | %.3f | **%.3f** | at most 0.5 |%n", ab / 1e6, ab / rate);
            System.out.printf(Locale.ROOT, "| R's airtime (A to R and R to B) | | %.1f %% | 100 %% |%n", 100 * (ar + ab) / rate);
            System.out.printf(Locale.ROOT, "%nThe two link threads waited for a CPU %.0f ms per second (together).%n", waited);
        }
    }

    // ---- 6. cost: server CPU per MB, 50 links shaped and not ----

    /**
     * 10 robots each sending to the next 5 as fast as the WSS takes it: 50 links at once. The
     * server's CPU time (utime + stime) and the bytes the robots read over {@code seconds}, after
     * one unmeasured second; shaped (every pair pinned to the cost rate), shaped without shared
     * airtime, and unshaped.
     */
    private void cost() throws Exception {
        int robots = 10;
        int peers = 5;
        long rate = Bitrate.parse(costRate);
        System.out.printf("%n## Cost: %d robots each sending to %d others (%d links), %s pinned, %d s after 1 unmeasured (load average %s)%n%n",
                robots, peers, robots * peers, Bitrate.format(rate), seconds, load());
        Set<String> pairs = new LinkedHashSet<>();
        for (int i = 0; i < robots; i++) {
            for (int k = 1; k <= peers; k++) {
                int j = (i + k) % robots;
                pairs.add("N" + Math.min(i, j) + ":N" + Math.max(i, j) + ":" + rate + ":2");
            }
        }
        String pins = "wss.force.up=" + String.join(",", pairs);
        Cost shaped = costRun(robots, peers, "wss.shaping=on", pins);
        Cost unshared = costRun(robots, peers, "wss.shaping=on", "wss.shaping.airtime=false", pins);
        Cost unshaped = costRun(robots, peers, "wss.shaping=off");
        System.out.println("| run | MB/s forwarded | mean radio busy (from bytes) | server CPU % of one core | server CPU ms per MB "
                + "| shaped/this per MB | link threads run, times/s (all 50) | link threads waited for a CPU, ms/s (all 50) |");
        System.out.println("|---|---|---|---|---|---|---|---|");
        List<Cost> all = List.of(shaped, unshared, unshaped);
        List<String> names = List.of("shaped, airtime shared", "shaped, wss.shaping.airtime=false", "unshaped (wss.shaping=off)");
        for (int i = 0; i < all.size(); i++) {
            Cost run = all.get(i);
            // Each byte keeps two radios busy for 8 / rate seconds; the mean over the robots' radios.
            String busy = i != 0 ? "" : String.format(Locale.ROOT, "%.0f %%", 100 * run.bytesPerSecond() * 8 / rate * 2 / robots);
            System.out.printf(Locale.ROOT, "| %s | %.2f | %s | %.0f | %.2f | %s | %.0f | %.0f |%n", names.get(i), run.bytesPerSecond() / 1e6, busy,
                    100.0 * run.cpuNanos / run.wallNanos, run.cpuMsPerMb(),
                    i == 0 ? "" : String.format(Locale.ROOT, "**%.1fx**", shaped.cpuMsPerMb() / run.cpuMsPerMb()),
                    run.timesRun / (run.wallNanos / 1e9), run.waitedNanos / 1e6 / (run.wallNanos / 1e9));
        }
    }

    private record Cost(long bytes, long cpuNanos, long wallNanos, long waitedNanos, long timesRun) {
        double bytesPerSecond() {
            return bytes * (double) SECOND / wallNanos;
        }

        double cpuMsPerMb() {
            return cpuNanos / 1e6 / (bytes / 1e6);
        }
    }

    private Cost costRun(int robots, int peers, String... properties) throws Exception {
        Counter received = new Counter(false);
        List<Sink> sinks = new ArrayList<>();
        List<ControlClient> controls = new ArrayList<>();
        List<Sender> senders = new ArrayList<>();
        try (WssProcess wss = WssProcess.start(properties)) {
            try {
                for (int i = 0; i < robots; i++) {
                    Sink sink = new Sink(received, null);
                    sinks.add(sink);
                    controls.add(new ControlClient(wss.controlPort, "N" + i, sink.port()));
                }
                List<Integer> ports = new ArrayList<>();
                for (int i = 0; i < robots; i++) {
                    for (int k = 1; k <= peers; k++) {
                        ports.add(controls.get(i).dns("N" + (i + k) % robots));
                    }
                }
                for (int port : ports) {
                    senders.add(Sender.start(port, Long.MAX_VALUE, null));
                }
                Thread.sleep(1000);
                Map<String, Long> waits = ProcessStats.linkThreadsWaitNanos(wss.pid());
                Map<String, Long> runs = ProcessStats.linkThreads(wss.pid(), ProcessStats.TIMES_RUN);
                long cpu0 = ProcessStats.cpuNanos(wss.pid());
                long bytes0 = received.total();
                long t0 = System.nanoTime();
                Thread.sleep(seconds * 1000L);
                long cpu1 = ProcessStats.cpuNanos(wss.pid());
                long bytes1 = received.total();
                long t1 = System.nanoTime();
                long waited = ProcessStats.waitedBetween(waits, ProcessStats.linkThreadsWaitNanos(wss.pid()));
                long wakeUps = ProcessStats.waitedBetween(runs, ProcessStats.linkThreads(wss.pid(), ProcessStats.TIMES_RUN));
                return new Cost(bytes1 - bytes0, cpu1 - cpu0, t1 - t0, waited, wakeUps);
            } finally {
                // The load stops before the server does (a server gone first would break every sender's pipe).
                for (Sender sender : senders) {
                    sender.stop();
                }
                for (ControlClient control : controls) {
                    control.close();
                }
                for (Sink sink : sinks) {
                    sink.close();
                }
            }
        }
    }

    // ---- 7. bulk integrity: a two-hop shaped path, hashed at both ends ----

    /**
     * {@code bulkBytes} of seeded random bytes from A to R through the WSS, R's program relaying
     * every byte to B through the WSS, at the default table's rate for the Noop model's 0 dBm
     * (54 Mbit/s) and the default delay (2 ms); SHA-256 of what A wrote and of what B read.
     * R's radio pays twice, so the expected time is bytes x 8 / 27 Mbit/s.
     */
    private void bulk() throws Exception {
        System.out.printf("%n## Bulk integrity: %d MB from A to R to B through the WSS, shaping on, default rate table and delay "
                + "(Noop model: 54 Mbit/s, 2 ms), load average %s%n%n", bulkBytes / 1_000_000, load());
        Counter atR = new Counter(false);
        Counter atB = new Counter(false);
        MessageDigest sent = sha256();
        MessageDigest got = sha256();
        try (WssProcess wss = WssProcess.start("wss.shaping=on");
                Sink b = new Sink(atB, got); RelayRobot relay = new RelayRobot(atR);
                ControlClient robotB = new ControlClient(wss.controlPort, "B", b.port());
                ControlClient robotR = new ControlClient(wss.controlPort, "R", relay.port());
                ControlClient robotA = new ControlClient(wss.controlPort, "A", 1)) {
            relay.target(robotR.dns("B"));
            int port = robotA.dns("R");
            long start = System.nanoTime();
            Sender sender = Sender.start(port, bulkBytes, sent);
            WaitSampler waits = WaitSampler.start(wss.pid());
            double expected = bulkBytes * 8.0 / (Bitrate.parse("54M") / 2.0);
            boolean ended = b.ended.await((long) (expected * 3 + 60), TimeUnit.SECONDS);
            long end = b.endNs.get();
            double waited = waits.stop() / 1e6 / ((end - start) / 1e9);
            sender.stop();
            double elapsed = (end - start) / 1e9;
            String sentHash = sender.done ? HexFormat.of().formatHex(sent.digest()) : "(sender did not finish)";
            String gotHash = ended ? HexFormat.of().formatHex(got.digest()) : "(B did not see the end of the stream)";
            System.out.println("| bytes sent | bytes at R | bytes at B | seconds | Mbit/s A to B | of 27 Mbit/s (half of 54) | SHA-256 identical |");
            System.out.println("|---|---|---|---|---|---|---|");
            System.out.printf(Locale.ROOT, "| %d | %d | %d | %.2f | %.3f | %.3f | **%s** |%n", sender.sent, atR.total(), atB.total(),
                    elapsed, atB.total() * 8 / elapsed / 1e6, atB.total() * 8 / elapsed / 27e6,
                    ended && sentHash.equals(gotHash) ? "yes" : "NO");
            System.out.println();
            System.out.println("SHA-256 written by A: " + sentHash);
            System.out.println("SHA-256 read by B:    " + gotHash);
            System.out.printf(Locale.ROOT, "The two link threads waited for a CPU %.0f ms per second (together).%n", waited);
        }
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    // ---- the robots ----

    /** Bytes a robot read, and (with history) when: one (time, running total) per read. */
    static final class Counter {
        private final boolean history;
        private final AtomicLong total = new AtomicLong();
        private long[] times = new long[4096];
        private long[] totals = new long[4096];
        private int count;

        Counter(boolean history) {
            this.history = history;
        }

        void add(int bytes, long nowNs) {
            long now = total.addAndGet(bytes);
            if (history) {
                synchronized (this) {
                    if (count == times.length) {
                        times = Arrays.copyOf(times, count * 2);
                        totals = Arrays.copyOf(totals, count * 2);
                    }
                    times[count] = nowNs;
                    totals[count] = now;
                    count++;
                    notifyAll();
                }
            }
        }

        long total() {
            return total.get();
        }

        /** When the first byte arrived, waiting for it at most {@code timeoutNs}. */
        synchronized long awaitFirst(long timeoutNs) throws InterruptedException, IOException {
            long deadline = System.nanoTime() + timeoutNs;
            while (count == 0) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    throw new IOException("no byte arrived");
                }
                TimeUnit.NANOSECONDS.timedWait(this, left);
            }
            return times[0];
        }

        /** When the first read after {@code afterNs} was, waiting for it at most {@code timeoutNs}. */
        synchronized long awaitAfter(long afterNs, long timeoutNs) throws InterruptedException, IOException {
            long deadline = System.nanoTime() + timeoutNs;
            while (count == 0 || times[count - 1] - afterNs <= 0) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    throw new IOException("no byte arrived");
                }
                TimeUnit.NANOSECONDS.timedWait(this, left);
            }
            int first = count - 1;
            while (first > 0 && times[first - 1] - afterNs > 0) {
                first--;
            }
            return times[first];
        }

        /** When the running total first reached {@code bytes}, waiting for it at most {@code timeoutNs}. */
        synchronized long awaitTotal(long bytes, long timeoutNs) throws InterruptedException, IOException {
            long deadline = System.nanoTime() + timeoutNs;
            while (count == 0 || totals[count - 1] < bytes) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    throw new IOException("only " + (count == 0 ? 0 : totals[count - 1]) + " of " + bytes + " bytes arrived");
                }
                TimeUnit.NANOSECONDS.timedWait(this, left);
            }
            int first = count - 1;
            while (first > 0 && totals[first - 1] >= bytes) {
                first--;
            }
            return times[first];
        }

        /** Bytes read by {@code nowNs}: the running total of the last read at or before it. */
        synchronized long at(long nowNs) {
            int low = 0;
            int high = count - 1;
            int found = -1;
            while (low <= high) {
                int middle = (low + high) >>> 1;
                if (times[middle] - nowNs <= 0) {
                    found = middle;
                    low = middle + 1;
                } else {
                    high = middle - 1;
                }
            }
            return found < 0 ? 0 : totals[found];
        }

        long between(long fromNs, long toNs) {
            return at(toNs) - at(fromNs);
        }
    }

    /** A robot's accept port that reads every connection to its end, counting (and optionally hashing) what it reads. */
    static final class Sink implements AutoCloseable {
        private final ServerSocket server;
        private final Counter counter;
        private final MessageDigest digest;
        private final List<Socket> open = new ArrayList<>();
        final CountDownLatch ended = new CountDownLatch(1);
        final AtomicLong endNs = new AtomicLong();

        Sink(Counter counter, MessageDigest digest) throws IOException {
            this.counter = counter;
            this.digest = digest;
            server = new ServerSocket();
            server.bind(new InetSocketAddress("127.0.0.1", 0), 64);
            daemon(this::acceptLoop, "sink " + server.getLocalPort());
        }

        int port() {
            return server.getLocalPort();
        }

        private void acceptLoop() {
            while (!server.isClosed()) {
                try {
                    Socket socket = server.accept();
                    synchronized (open) {
                        open.add(socket);
                    }
                    daemon(() -> read(socket), "sink read");
                } catch (IOException e) {
                    return;
                }
            }
        }

        private void read(Socket socket) {
            byte[] buffer = new byte[CHUNK];
            try (socket) {
                InputStream in = socket.getInputStream();
                int read;
                while ((read = in.read(buffer)) >= 0) {
                    long now = System.nanoTime();
                    if (digest != null) {
                        digest.update(buffer, 0, read);
                    }
                    counter.add(read, now);
                }
                endNs.set(System.nanoTime());
                ended.countDown();
            } catch (IOException ignored) {
                // Closed at the end of a run.
            }
        }

        @Override
        public void close() throws IOException {
            server.close();
            synchronized (open) {
                for (Socket socket : open) {
                    socket.close();
                }
            }
        }
    }

    /** A relay robot's program: every byte read on a connection to its accept port is written to the target port, in order. */
    static final class RelayRobot implements AutoCloseable {
        private final ServerSocket server;
        private final Counter counter;
        private final List<Socket> open = new ArrayList<>();
        private volatile int target;

        RelayRobot(Counter counter) throws IOException {
            this.counter = counter;
            server = new ServerSocket();
            server.bind(new InetSocketAddress("127.0.0.1", 0), 64);
            daemon(this::acceptLoop, "relay " + server.getLocalPort());
        }

        int port() {
            return server.getLocalPort();
        }

        /** The port it relays to (its WSS port for the next robot). */
        void target(int port) {
            target = port;
        }

        private void acceptLoop() {
            while (!server.isClosed()) {
                try {
                    Socket in = server.accept();
                    Socket out = new Socket();
                    out.setTcpNoDelay(true);
                    out.connect(new InetSocketAddress("127.0.0.1", target), 5000);
                    synchronized (open) {
                        open.add(in);
                        open.add(out);
                    }
                    daemon(() -> relay(in, out), "relay copy");
                } catch (IOException e) {
                    return;
                }
            }
        }

        private void relay(Socket in, Socket out) {
            byte[] buffer = new byte[CHUNK];
            try (in; out) {
                InputStream from = in.getInputStream();
                OutputStream to = out.getOutputStream();
                int read;
                while ((read = from.read(buffer)) >= 0) {
                    counter.add(read, System.nanoTime());
                    to.write(buffer, 0, read);
                }
                out.shutdownOutput();
                in.shutdownOutput();
                // Wait for the WSS to end the stream to B after the last byte (closing now is fine too: nothing unread).
                out.getInputStream().read();
            } catch (IOException ignored) {
                // Closed at the end of a run.
            }
        }

        @Override
        public void close() throws IOException {
            server.close();
            synchronized (open) {
                for (Socket socket : open) {
                    socket.close();
                }
            }
        }
    }

    /** A robot writing to a WSS port as fast as it is taken, a limit of bytes or until stopped. */
    static final class Sender {
        private final Socket socket = new Socket();
        private final long limit;
        private final MessageDigest digest;
        private volatile boolean stopped;
        volatile long sent;
        volatile boolean done;

        private Sender(long limit, MessageDigest digest) {
            this.limit = limit;
            this.digest = digest;
        }

        /**
         * Connects and starts writing: zeros, or with a digest seeded random bytes it hashes.
         * With a limit, ends its stream after it.
         */
        static Sender start(int port, long limit, MessageDigest digest) throws IOException {
            Sender sender = new Sender(limit, digest);
            sender.socket.setTcpNoDelay(true);
            sender.socket.connect(new InetSocketAddress("127.0.0.1", port), 5000);
            daemon(sender::write, "sender " + port);
            return sender;
        }

        private void write() {
            byte[] chunk = new byte[CHUNK];
            Random random = new Random(16);
            try {
                OutputStream out = socket.getOutputStream();
                long total = 0;
                while (total < limit && !stopped) {
                    int n = (int) Math.min(chunk.length, limit - total);
                    if (digest != null) {
                        random.nextBytes(chunk);
                        digest.update(chunk, 0, n);
                    }
                    out.write(chunk, 0, n);
                    total += n;
                    sent = total;
                }
                if (total == limit) {
                    socket.shutdownOutput();
                    done = true;
                }
            } catch (IOException e) {
                if (!stopped) {
                    System.err.println("  sender: " + e);
                }
            }
        }

        void stop() throws IOException {
            stopped = true;
            socket.close();
        }
    }

    // ---- helpers ----

    /**
     * How long the server's link threads waited for a CPU while links come and go: reads them
     * every 100 ms and adds up, per thread, its last reading less its first.
     */
    private static final class WaitSampler {
        private final Map<String, Long> first = new java.util.concurrent.ConcurrentHashMap<>();
        private final Map<String, Long> last = new java.util.concurrent.ConcurrentHashMap<>();
        private volatile boolean stopped;
        private final Thread thread;

        private WaitSampler(long pid) {
            thread = new Thread(() -> {
                while (!stopped) {
                    try {
                        Map<String, Long> now = ProcessStats.linkThreadsWaitNanos(pid);
                        now.forEach(first::putIfAbsent);
                        last.putAll(now);
                        Thread.sleep(100);
                    } catch (IOException | InterruptedException e) {
                        return;
                    }
                }
            }, "wait sampler");
            thread.setDaemon(true);
            thread.start();
        }

        static WaitSampler start(long pid) {
            return new WaitSampler(pid);
        }

        /** Stops sampling; the waits added up, in nanoseconds. */
        long stop() throws InterruptedException {
            stopped = true;
            thread.join();
            return ProcessStats.waitedBetween(first, last);
        }
    }

    private static void daemon(Runnable task, String name) {
        Thread thread = new Thread(null, task, name, 256 * 1024);
        thread.setDaemon(true);
        thread.start();
    }

    private static void sleepUntil(long nanoTime) throws InterruptedException {
        long left;
        while ((left = nanoTime - System.nanoTime()) > 0) {
            TimeUnit.NANOSECONDS.sleep(left);
        }
    }

    private static String load() {
        try {
            String[] fields = Files.readString(Path.of("/proc/loadavg")).split(" ");
            return fields[0] + " " + fields[1] + " " + fields[2];
        } catch (IOException e) {
            return "unknown";
        }
    }
}
