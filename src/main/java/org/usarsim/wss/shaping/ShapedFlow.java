package org.usarsim.wss.shaping;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.WritableByteChannel;
import java.util.ArrayDeque;

/**
 * One direction of one shaped link: the bytes read from one robot and not yet written to the
 * other, and when each may be written. The link's thread drives it, telling it the time at every
 * step: it {@link #accept}s what it read (at most {@link #room()}), {@link #writeTo}s the target
 * what is due, and waits at most {@link #nanosUntilNext} before asking again.
 *
 * <p>Bytes go on the air in order, lazily: whenever the direction's last grant starts within
 * {@link #LOOKAHEAD_NS}, the bytes not yet on the air ask its {@link Airtime.Hop} for the next
 * grant, at the rate the link has at that moment, so a rate change reaches every byte not yet
 * booked at the next step (grants already booked, at most a few milliseconds of airtime, keep
 * their rate). So a busy direction holds one grant on the air and books at most two quanta
 * ahead, and directions sharing a radio take turns. Bytes may be written at their grant's end plus the delay: a chunk
 * read at t over an idle radio is due at t + delay + its bytes x 8 / rate.
 *
 * <p>Nothing is lost, reordered or duplicated: shaping only changes when bytes are written. The
 * memory is bounded by {@link #capacity()}: rate x (delay + queue), the queue
 * ({@code wss.shaping.queueMs}, 100 ms by default) being what a radio's queue would hold; a
 * direction that holds that much reads no more, and TCP's back-pressure reaches the sender.
 *
 * <p>Used by one thread; it never reads a clock nor blocks.
 */
public final class ShapedFlow {

    /**
     * How far ahead a busy direction books its grants: the next is booked once the last one
     * starts within two quanta (4 ms), so that a link thread woken a few milliseconds late (a
     * busy machine) finds its radio's next grants already booked instead of an idle radio and
     * lost airtime.
     */
    static final long LOOKAHEAD_NS = 2 * Airtime.QUANTUM_NS;

    /** The least a direction may hold whatever its rate: one frame's payload (so that a link at 1 bit/s still reads). */
    public static final int MIN_HELD = 1500;

    private final Airtime.Hop hop;
    private final int queueMs;
    private long bitsPerSecond;
    private int delayMs;
    private long capacity;
    /** Read and not yet written, in order; each buffer's position is what was written of it. */
    private final ArrayDeque<ByteBuffer> chunks = new ArrayDeque<>();
    /** Grants whose bytes are not yet due, in order. */
    private final ArrayDeque<Slot> slots = new ArrayDeque<>();
    // Offsets in the stream of bytes this direction carries, received >= granted >= released >= written.
    private long received;
    private long granted;
    private long released;
    private long written;
    /** The part of byte {@code granted} already on the air, in bit x nanoseconds (below {@link #BYTE}). */
    private long carried;
    private long lastStartNs;
    private boolean anyGrant;
    /** The rate or the delay changed since the last step: the grants not yet begun are counted again. */
    private boolean changed;

    /** One byte in bit x nanoseconds: a grant of d ns at R bit/s carries R x d of them. */
    private static final long BYTE = 8_000_000_000L;

    /**
     * One grant of airtime and what it carries: the stream from {@code fromOffset} (with
     * {@code fromCarried} of the next byte already on the air before it) to {@code toOffset},
     * due at {@code dueNs}.
     */
    private static final class Slot {
        final long startNs;
        final long endNs;
        final long fromOffset;
        final long fromCarried;
        long toOffset;
        long dueNs;

        Slot(Airtime.Grant grant, long fromOffset, long fromCarried) {
            this.startNs = grant.startNs();
            this.endNs = grant.endNs();
            this.fromOffset = fromOffset;
            this.fromCarried = fromCarried;
        }
    }

    /**
     * A direction that sends through {@code hop} at {@code bitsPerSecond} with {@code delayMs}
     * of delay and a queue of {@code queueMs} ({@code wss.shaping.queueMs}); it owns the hop and closes it.
     */
    public ShapedFlow(Airtime.Hop hop, long bitsPerSecond, int delayMs, int queueMs) {
        if (queueMs < ShapingConfig.MIN_QUEUE_MS || queueMs > ShapingConfig.MAX_QUEUE_MS) {
            throw new IllegalArgumentException("a queue of " + ShapingConfig.MIN_QUEUE_MS + " to " + ShapingConfig.MAX_QUEUE_MS
                    + " ms, not " + queueMs);
        }
        this.hop = hop;
        this.queueMs = queueMs;
        setConditions(bitsPerSecond, delayMs);
    }

    /**
     * The bytes a direction may hold: rate x (delay + queue) / 8, at least {@link #MIN_HELD}.
     * The delay's bytes are in flight; the queue's wait their turn on the air, as a radio's
     * queue holds frames (issue 27: a link held seconds). A queue of at least
     * {@link ShapingConfig#MIN_QUEUE_MS} covers the grants booked ahead (8 ms), so the radio is
     * kept busy at full rate.
     */
    public static long capacity(long bitsPerSecond, int delayMs, int queueMs) {
        return Math.max(MIN_HELD, Bitrate.bytesIn((delayMs + (long) queueMs) * 1_000_000L, bitsPerSecond));
    }

    /**
     * The link's rate and delay from now on (the pair's strength changed, or an operator forced
     * them): bytes not yet on the air go at the new rate and wait the new delay; the capacity follows.
     */
    public void setConditions(long bitsPerSecond, int delayMs) {
        if (bitsPerSecond < 1 || bitsPerSecond > Bitrate.MAX) {
            throw new IllegalArgumentException("a rate from 1 to " + Bitrate.MAX + " bit/s, not " + bitsPerSecond);
        }
        if (delayMs < ShapingConfig.MIN_DELAY_MS || delayMs > ShapingConfig.MAX_DELAY_MS) {
            throw new IllegalArgumentException("a delay from " + ShapingConfig.MIN_DELAY_MS + " to "
                    + ShapingConfig.MAX_DELAY_MS + " ms, not " + delayMs);
        }
        changed |= bitsPerSecond != this.bitsPerSecond || delayMs != this.delayMs;
        this.bitsPerSecond = bitsPerSecond;
        this.delayMs = delayMs;
        this.capacity = capacity(bitsPerSecond, delayMs, queueMs);
    }

    /** The rate in bit/s. */
    public long rate() {
        return bitsPerSecond;
    }

    /** The delay in milliseconds. */
    public int delayMs() {
        return delayMs;
    }

    /** The most bytes this direction holds at its present rate and delay. */
    public long capacity() {
        return capacity;
    }

    /** The bytes read and not yet written. */
    public long held() {
        return received - written;
    }

    /** How many bytes may be read now: the capacity less what is held; 0 means read nothing. */
    public int room() {
        return (int) Math.max(0, Math.min(Integer.MAX_VALUE, capacity - held()));
    }

    /**
     * Takes the bytes read at {@code nowNs} (all of {@code bytes}' remaining ones, which it
     * copies; the buffer's position moves to its limit) and asks for their airtime.
     *
     * @throws IllegalStateException if they are more than {@link #room()}
     */
    public void accept(ByteBuffer bytes, long nowNs) {
        int count = bytes.remaining();
        if (count > room()) {
            throw new IllegalStateException(count + " bytes read with room for " + room());
        }
        if (count > 0) {
            byte[] copy = new byte[count];
            bytes.get(copy);
            chunks.addLast(ByteBuffer.wrap(copy));
            received += count;
        }
        pump(nowNs);
    }

    /** How many bytes may be written at {@code nowNs}. */
    public long due(long nowNs) {
        pump(nowNs);
        return released - written;
    }

    /**
     * Writes what is due at {@code nowNs} to {@code out}, in order, until all of it is written or
     * {@code out} takes no more (a non-blocking channel that is full).
     *
     * @return the bytes written
     */
    public int writeTo(WritableByteChannel out, long nowNs) throws IOException {
        pump(nowNs);
        int total = 0;
        while (written < released) {
            ByteBuffer head = chunks.peekFirst();
            head.limit((int) Math.min(head.capacity(), head.position() + (released - written)));
            int count = out.write(head);
            written += count;
            total += count;
            if (head.hasRemaining()) {
                break;
            }
            if (head.position() == head.capacity()) {
                chunks.pollFirst();
            }
        }
        return total;
    }

    /**
     * How long from {@code nowNs} until this direction has something new to do: bytes falling
     * due, or its turn to ask for more airtime; 0 if that is now, {@link Long#MAX_VALUE} if
     * nothing is scheduled (it holds nothing, or only bytes already due: those wait for the
     * target to take them, not for time).
     */
    public long nanosUntilNext(long nowNs) {
        pump(nowNs);
        long next = Long.MAX_VALUE;
        if (!slots.isEmpty()) {
            next = Math.max(0, slots.peekFirst().dueNs - nowNs);
        }
        if (granted < received) {
            next = Math.min(next, Math.max(0, lastStartNs - LOOKAHEAD_NS - nowNs));
        }
        return next;
    }

    /** Ends the direction's hop; what it still holds is dropped with it. */
    public void close() {
        hop.close();
    }

    /**
     * Counts again, at the present rate and delay, the grants that have not begun (after a
     * change), takes grants while it is this direction's turn, then marks what has fallen due.
     */
    private void pump(long nowNs) {
        if (changed) {
            changed = false;
            recount(nowNs);
        }
        while (granted < received && (!anyGrant || lastStartNs - nowNs <= LOOKAHEAD_NS)) {
            Slot slot = new Slot(hop.grant(nanosFor(received - granted), nowNs), granted, carried);
            fill(slot);
            slots.addLast(slot);
            lastStartNs = slot.startNs;
            anyGrant = true;
        }
        while (!slots.isEmpty() && slots.peekFirst().dueNs - nowNs <= 0) {
            released = slots.pollFirst().toOffset;
        }
    }

    /**
     * The airtime the next grant asks for: one quantum, or less if that carries all of
     * {@code wanted} bytes (the time for them, rounded up: a byte is never early).
     */
    private long nanosFor(long wanted) {
        long quantum = carried + bitsPerSecond * Airtime.QUANTUM_NS;
        if (wanted > quantum / BYTE) {
            return Airtime.QUANTUM_NS;
        }
        long needed = wanted * BYTE - carried;
        return Math.max(1, Math.min(Airtime.QUANTUM_NS, (needed + bitsPerSecond - 1) / bitsPerSecond));
    }

    /** What {@code slot} carries at the present rate, from where the stream stands, and when it is due. */
    private void fill(Slot slot) {
        long bitNanos = carried + bitsPerSecond * (slot.endNs - slot.startNs);
        long bytes = Math.min(bitNanos / BYTE, received - granted);
        granted += bytes;
        carried = granted == received ? 0 : bitNanos - bytes * BYTE;
        slot.toOffset = granted;
        slot.dueNs = slot.endNs + delayMs * 1_000_000L;
    }

    /**
     * After a change of rate or delay: the grants booked but not yet begun at {@code nowNs} carry
     * what the new rate puts in them, due after the new delay. The one on the air keeps its own.
     */
    private void recount(long nowNs) {
        Slot first = null;
        for (var it = slots.descendingIterator(); it.hasNext();) {
            Slot slot = it.next();
            if (slot.startNs - nowNs <= 0) {
                break;
            }
            first = slot;
        }
        if (first == null) {
            return;
        }
        granted = first.fromOffset;
        carried = first.fromCarried;
        boolean counting = false;
        for (Slot slot : slots) {
            counting |= slot == first;
            if (counting) {
                fill(slot);
            }
        }
    }
}
