package org.usarsim.wss.shaping;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.usarsim.wss.routes.Hop;
import org.usarsim.wss.routes.RouteRule;
import org.usarsim.wss.shaping.SimulatedLinks.Lane;

/**
 * Issue 34's relay chains on a moved clock (docs/routes.md, "The bound against reality"): the
 * real shaping ({@link Airtime#shared()}, {@link ShapedFlow}) of the hops R0 to R1 to .. Rk, each
 * driven as its link's thread drives it (it writes what is due, reads what fits, waits until its
 * flow's next time or until its input has bytes or its output room), each relay a program that
 * wakes when bytes reach it and passes them all on (socat), through a buffer of
 * {@code relayBuffer} bytes between the two hops (its sockets' buffers and the WSS's), R0
 * sending without end. A busy machine is a lateness: every wake-up of a link's thread or a relay
 * program comes that much after it was due, drawn from an exponential distribution of the given
 * mean (0: threads that wake on time). Deterministic: the same arguments give the same bytes.
 */
final class RelayChainSimulation {

    /** The hub's chunk (the benchmark's TestHub config). */
    static final int CHUNK = 65536;

    /** The five chains of docs/performance.md's table, in bit/s. */
    static final long[][] CHAINS = {{6_000_000}, {12_000_000, 6_000_000}, {12_000_000, 6_000_000, 12_000_000},
        {12_000_000, 12_000_000, 12_000_000}, {6_000_000, 12_000_000, 6_000_000}};

    private final SimulatedLinks links = new SimulatedLinks(Airtime.shared(), 0, false);
    private final List<Lane> lanes = new ArrayList<>();
    private final long meanLateNs;
    private final Random late;
    /** Whether of threads due at the same instant the last hop's goes first (else the first hop's). */
    private final boolean lastFirst;
    /**
     * When each thread wakes next (Long.MAX_VALUE: when its sockets say): the hops' link threads
     * first, then the relays' programs.
     */
    private final long[] wake;
    /** What each relay program has passed on so far: what the next hop can read. */
    private final long[] relayed;

    RelayChainSimulation(long[] rates, long relayBuffer, long meanLateNs, long seed, boolean lastFirst) {
        this(rates, relayBuffer, 0, meanLateNs, seed, lastFirst);
    }

    /**
     * As the other, the relays handing room back to the hop into them only in steps of at least
     * {@code roomStep} bytes (0: byte by byte), as a relay's TCP sockets and program do (a window
     * opened by a segment, a program's read of a block).
     */
    RelayChainSimulation(long[] rates, long relayBuffer, long roomStep, long meanLateNs, long seed, boolean lastFirst) {
        this.meanLateNs = meanLateNs;
        this.late = new Random(seed);
        this.lastFirst = lastFirst;
        relayed = new long[rates.length - 1];
        for (int i = 0; i < rates.length; i++) {
            int relay = i - 1;
            SimulatedLinks.Source source = i == 0 ? SimulatedLinks.endless() : () -> relayed[relay];
            lanes.add(links.add("R" + i, "R" + (i + 1), rates[i], ShapingConfig.DEFAULT_DELAY_MS, CHUNK, source));
        }
        for (int i = 0; i + 1 < lanes.size(); i++) {
            Lane into = lanes.get(i);
            Lane onward = lanes.get(i + 1);
            into.takes = () -> {
                long free = Math.max(0, relayBuffer - (into.delivered - onward.read));
                return free >= roomStep ? free : 0;
            };
        }
        wake = new long[2 * rates.length - 1];
        Arrays.fill(wake, rates.length, wake.length, Long.MAX_VALUE);
    }

    /** What the last hop delivered so far, in bytes. */
    long delivered() {
        return lanes.get(lanes.size() - 1).delivered;
    }

    /** Runs the threads until {@code endNs}. */
    void runUntil(long endNs) {
        while (true) {
            int next = 0;
            for (int i = 1; i < wake.length; i++) {
                if (wake[i] < wake[next] || (lastFirst && wake[i] == wake[next])) {
                    next = i;
                }
            }
            if (wake[next] > endNs) {
                links.now = endNs;
                return;
            }
            links.now = Math.max(links.now, wake[next]);
            if (next < lanes.size()) {
                turn(next);
            } else {
                relay(next - lanes.size());
            }
        }
    }

    /** Lane {@code i}'s thread awake: writes what is due, reads what fits, and sleeps; wakes its neighbours' threads. */
    private void turn(int i) {
        Lane lane = lanes.get(i);
        long now = links.now;
        long deliveredBefore = lane.delivered;
        long readBefore = lane.read;
        lane.turn();
        long until = lane.flow.nanosUntilNext(now);
        wake[i] = until == Long.MAX_VALUE ? Long.MAX_VALUE : now + until + lateness();
        if (lane.delivered > deliveredBefore && i + 1 < lanes.size()) {
            wakeOn(lanes.size() + i, now); // the relay's input has bytes
        }
        if (lane.read > readBefore && i > 0 && lanes.get(i - 1).flow.due(now) > 0) {
            wakeOn(i - 1, now); // its output has room
        }
    }

    /** Relay {@code j}'s program awake: passes on all it received (its buffer is the one shared with the hops), wakes the next hop. */
    private void relay(int j) {
        wake[lanes.size() + j] = Long.MAX_VALUE;
        long received = lanes.get(j).delivered;
        if (received > relayed[j]) {
            relayed[j] = received;
            wakeOn(j + 1, links.now);
        }
    }

    private void wakeOn(int i, long now) {
        wake[i] = Math.min(wake[i], now + lateness());
    }

    private long lateness() {
        return meanLateNs == 0 ? 0 : (long) (-Math.log(1 - late.nextDouble()) * meanLateNs);
    }

    /** The steady throughput in bit/s: what the last hop delivers over {@code measureNs} after {@code warmNs}. */
    static double throughput(long[] rates, long relayBuffer, long meanLateNs, long warmNs, long measureNs) {
        return throughput(new RelayChainSimulation(rates, relayBuffer, meanLateNs, 34, false), warmNs, measureNs);
    }

    /** As the other, of {@code chain} (new). */
    static double throughput(RelayChainSimulation chain, long warmNs, long measureNs) {
        chain.runUntil(warmNs);
        long from = chain.delivered();
        chain.runUntil(warmNs + measureNs);
        return (chain.delivered() - from) * 8e9 / measureNs;
    }

    /** The route's rate as the hub computes it: {@link RouteRule#FASTEST_SHARED_AIRTIME}'s bound of these hops. */
    static long bound(long[] rates) {
        List<Hop> hops = new ArrayList<>();
        for (int i = 0; i < rates.length; i++) {
            hops.add(new Hop("R" + i, "R" + (i + 1), Double.NaN, rates[i]));
        }
        return RouteRule.FASTEST_SHARED_AIRTIME.bound(hops);
    }

    /** {@code [relayBuffer [roomStep [meanLateMs...]]]}: the five chains of docs/performance.md at each lateness. */
    public static void main(String[] args) {
        long buffer = args.length > 0 ? Long.parseLong(args[0]) : 160 * 1024;
        long step = args.length > 1 ? Long.parseLong(args[1]) : 0;
        double[] lates = args.length > 2 ? Arrays.stream(args, 2, args.length).mapToDouble(Double::parseDouble).toArray()
                : new double[] {0};
        for (double lateMs : lates) {
            for (long[] rates : CHAINS) {
                long bound = bound(rates);
                double t = throughput(new RelayChainSimulation(rates, buffer, step, (long) (lateMs * 1e6), 34, false),
                        5_000_000_000L, 20_000_000_000L);
                System.out.printf(Locale.ROOT, "step %d late %.2f ms buffer %d %s: %.3f Mbit/s of %.3f: %.3f%n", step, lateMs, buffer,
                        Arrays.toString(rates), t / 1e6, bound / 1e6, t / bound);
            }
        }
    }
}
