package org.usarsim.wss.shaping;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.PriorityQueue;
import java.util.SplittableRandom;
import java.util.random.RandomGenerator;

/**
 * One direction of a fixed UDP port's pair (docs/fixed-ports.md): the datagrams received and not
 * yet sent, and when each may be sent. Each datagram is carried whole or not at all.
 *
 * <p>Unshaped (a rate of 0), a datagram is due at once and never lost. Shaped, datagrams wait in a
 * bounded queue ({@link #capacity}; one that does not fit is dropped, the tail drop, counted), then
 * go on the air one after the other through the direction's {@link Airtime.Hop} at the pair's
 * rate; as a datagram leaves the queue (its airtime booked) the loss is drawn from a seeded
 * generator with the pair's loss percent, so a lost datagram still takes its airtime, as a radio's
 * lost frame does; one not lost is due at the end of its airtime plus the delay and its jitter
 * ({@link Jitter}, drawn per datagram): with {@code reorder} each at its own due time, so a later
 * one may overtake; without, never before the one before it (docs/shaping.md, "Jitter").
 *
 * @param <T> where a datagram goes (a session's socket, a sender's address): carried along, never looked at
 *
 * <p>Used by one thread; it never reads a clock nor blocks: every method is given the time.
 */
public final class DatagramFlow<T> {

    /** The largest UDP payload over IPv4: 65,535 - 8 (UDP header) - 20 (IP header). */
    public static final int MAX_DATAGRAM = 65_507;

    /** How much a shaped queue holds besides one largest datagram: what the rate carries in 100 ms. */
    static final long QUEUE_NS = 100_000_000L;

    /** A datagram going somewhere. */
    public record Datagram<T>(byte[] data, T to) {
    }

    private record Pending<T>(Datagram<T> datagram, long dueNs, long order) {
    }

    private final Airtime.Hop hop;
    private final SplittableRandom random;
    private long bitsPerSecond;
    /** The stage after the air: a datagram is due when it is off the air plus the delay. */
    private final Delay delay = new Delay(0);
    /** The stage after the delay: its jitter, per datagram. */
    private final Jitter jitter;
    /** Whether a datagram may overtake those before it by its jitter; without, each is due no sooner than the one before. */
    private final boolean reorder;
    private double lossPercent;
    /** The model's rule for the losses, instead of the percent; null: the percent. */
    private LossRule lossRule;
    private final ArrayDeque<Datagram<T>> queue = new ArrayDeque<>();
    private long queuedBytes;
    /** By due time, then in the order received. */
    private final PriorityQueue<Pending<T>> onTheWay = new PriorityQueue<>(
            Comparator.<Pending<T>>comparingLong(Pending::dueNs).thenComparingLong(Pending::order));
    private long received;
    private long lastDueNs;
    private long lastStartNs;
    private boolean anyBooked;
    private long droppedQueue;
    private long lost;

    /** A model's rule for losing a datagram (a {@code model.DatagramLoss}), drawn from the direction's generator. */
    @FunctionalInterface
    public interface LossRule {
        boolean lost(int bytes, long nowNs, RandomGenerator random);
    }

    /** A direction over {@code hop} (it owns the hop and closes it), its losses drawn from a generator seeded with {@code seed}. */
    public DatagramFlow(Airtime.Hop hop, long seed) {
        this(hop, seed, JitterDistribution.UNIFORM, false, 0);
    }

    /**
     * As the other, with a jitter of {@code distribution} (none until {@link #setJitterMs}) drawn
     * from a generator seeded with {@code jitterSeed}; {@code reorder}: datagrams may overtake.
     */
    public DatagramFlow(Airtime.Hop hop, long seed, JitterDistribution distribution, boolean reorder, long jitterSeed) {
        this.hop = hop;
        this.random = new SplittableRandom(seed);
        this.jitter = new Jitter(delay, distribution, jitterSeed, 0);
        this.reorder = reorder;
    }

    /** The delay's jitter from now on, in ms, for the datagrams not yet on the air. */
    public void setJitterMs(int ms) {
        jitter.set(ms);
    }

    /** A datagram on its way, due at {@code dueNs} (or after the one before it, without reordering). */
    private void onTheWay(Datagram<T> datagram, long dueNs) {
        long due = reorder || received == 0 || dueNs - lastDueNs >= 0 ? dueNs : lastDueNs;
        lastDueNs = due;
        onTheWay.add(new Pending<>(datagram, due, received++));
    }

    /** The bytes a shaped queue may hold at this rate: what it carries in 100 ms, plus one largest datagram. */
    public static long capacity(long bitsPerSecond) {
        return Bitrate.bytesIn(QUEUE_NS, bitsPerSecond) + MAX_DATAGRAM;
    }

    /** The pair's rate (0: unshaped), delay and loss percent from now on, for the datagrams not yet on the air. */
    public void setConditions(long bitsPerSecond, int delayMs, double lossPercent) {
        this.bitsPerSecond = bitsPerSecond;
        this.delay.set(delayMs);
        this.lossPercent = lossPercent;
    }

    /** The model's rule for the losses from now on, instead of the loss percent; null: the percent. */
    public void setLossRule(LossRule rule) {
        this.lossRule = rule;
    }

    /**
     * A datagram received at {@code nowNs}: queued, or dropped when a shaped queue has no room for it.
     *
     * @return false when it was dropped (counted in {@link #droppedQueue})
     */
    public boolean offer(byte[] data, T to, long nowNs) {
        Datagram<T> datagram = new Datagram<>(data, to);
        if (bitsPerSecond <= 0) {
            onTheWay(datagram, nowNs);
            return true;
        }
        if (queuedBytes + data.length > capacity(bitsPerSecond)) {
            droppedQueue++;
            return false;
        }
        queue.add(datagram);
        queuedBytes += data.length;
        book(nowNs);
        return true;
    }

    /** Books the airtime of the queue's head datagrams while the last booked one starts within the lookahead. */
    private void book(long nowNs) {
        while (!queue.isEmpty() && (!anyBooked || lastStartNs - (nowNs + OnTheAir.LOOKAHEAD_NS) <= 0)) {
            if (bitsPerSecond <= 0) {
                Datagram<T> datagram = queue.poll();
                queuedBytes -= datagram.data().length;
                onTheWay(datagram, nowNs);
                continue;
            }
            Datagram<T> datagram = queue.poll();
            queuedBytes -= datagram.data().length;
            // its airtime, an empty datagram's frame counted as a byte, taken in slots of at most a quantum
            long leftNs = airtimeNs(Math.max(1, datagram.data().length), bitsPerSecond);
            long end = nowNs;
            boolean first = true;
            while (leftNs > 0) {
                Airtime.Grant grant = hop.grant(Math.min(leftNs, Airtime.QUANTUM_NS), nowNs);
                if (first) {
                    lastStartNs = grant.startNs();
                    first = false;
                }
                leftNs -= grant.endNs() - grant.startNs();
                end = grant.endNs();
            }
            anyBooked = true;
            if (lossRule != null ? lossRule.lost(datagram.data().length, nowNs, random)
                    : lossPercent > 0 && random.nextDouble() * 100 < lossPercent) {
                lost++;
            } else {
                onTheWay(datagram, jitter.dueAt(delay.dueAt(end)));
            }
        }
    }

    /** The time {@code bytes} take on the air at {@code bitsPerSecond}, at least 1 ns. */
    static long airtimeNs(long bytes, long bitsPerSecond) {
        return Math.max(1, (long) Math.ceil(bytes * 8.0 * 1e9 / bitsPerSecond));
    }

    /** The datagrams due at {@code nowNs}, in order, for the caller to send now; the queue's next ones booked. */
    public List<Datagram<T>> due(long nowNs) {
        book(nowNs);
        List<Datagram<T>> due = new ArrayList<>();
        while (!onTheWay.isEmpty() && onTheWay.peek().dueNs() - nowNs <= 0) {
            due.add(onTheWay.poll().datagram());
        }
        return due;
    }

    /** Nanoseconds from {@code nowNs} until something is due or is to be booked; {@link Long#MAX_VALUE} when nothing waits. */
    public long nanosUntilNext(long nowNs) {
        long next = Long.MAX_VALUE;
        if (!onTheWay.isEmpty()) {
            next = Math.max(0, onTheWay.peek().dueNs() - nowNs);
        }
        if (!queue.isEmpty()) {
            next = Math.min(next, Math.max(0, lastStartNs - OnTheAir.LOOKAHEAD_NS - nowNs));
        }
        return next;
    }

    /** Whether nothing is queued or on the way. */
    public boolean idle() {
        return queue.isEmpty() && onTheWay.isEmpty();
    }

    /** Datagrams dropped because the queue had no room for them. */
    public long droppedQueue() {
        return droppedQueue;
    }

    /** Datagrams lost to the signal (drawn with the loss percent). */
    public long lost() {
        return lost;
    }

    /** Ends the direction: its hop is closed. */
    public void close() {
        hop.close();
    }
}
