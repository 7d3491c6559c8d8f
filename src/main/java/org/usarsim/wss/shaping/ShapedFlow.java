package org.usarsim.wss.shaping;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.WritableByteChannel;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * One direction of one shaped link: the bytes read from one robot and not yet written to the
 * other, and when each may be written. The link's thread drives it, telling it the time at every
 * step: it {@link #accept}s what it read (at most {@link #room()}), {@link #writeTo}s the target
 * what is due, and waits at most {@link #nanosUntilNext} before asking again.
 *
 * <p>Bytes go on the air in order, lazily: whenever the direction's last grant starts within
 * {@link #LOOKAHEAD_NS}, the bytes not yet on the air ask its {@link Airtime.Hop} for the next
 * grant, at the rate the link has at that moment. So a busy direction holds one grant on the air
 * and books at most two quanta ahead, and directions sharing a radio take turns. A rate change
 * reaches the link at its next step: the grant on the air carries at the new rate from the
 * change on, the grants booked ahead carry at the new rate, and every later grant is asked at it;
 * the grants keep their airtime. A grant's bytes may be written once its last byte is on the air
 * (its end, or sooner when it carries every byte held with time to spare), plus the delay: a chunk
 * read at t over an idle radio is due at t + delay + its bytes x 8 / rate.
 *
 * <p>Nothing is lost, reordered or duplicated: shaping only changes when bytes are written. The
 * memory is bounded by {@link #capacity()}: rate x (delay + queue), the queue
 * ({@code wss.shaping.queueMs}, 20 ms by default) being what a radio's queue would hold; a
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
    /** Grants whose bytes are not yet due or that are not yet over, in order. */
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
    /** The rate or the delay changed since the last step: the grants not yet over are counted again. */
    private boolean changed;
    /** Bytes were read since the last step while every byte held had its grant: the time booked to spare carries them. */
    private boolean arrived;

    /** One byte in bit x nanoseconds: a grant of d ns at R bit/s carries R x d of them. */
    private static final long BYTE = 8_000_000_000L;

    /**
     * A grant of airtime, or its part from a cut on, and what it carries: the stream from
     * {@code fromOffset} (with {@code fromCarried} of the next byte already on the air before it)
     * to {@code toOffset}, at {@code bitsPerSecond}, due at {@code dueNs} ({@code delayNs} after
     * its last byte is on the air).
     */
    private static final class Slot {
        final long startNs;
        long endNs;
        long fromOffset;
        long fromCarried;
        long bitsPerSecond;
        long delayNs;
        long toOffset;
        long dueNs;

        Slot(long startNs, long endNs) {
            this.startNs = startNs;
            this.endNs = endNs;
        }

        /**
         * Cuts it at {@code nowNs}, while it is on the air: this part keeps the bytes whole on
         * the air by then, due {@link #delayNs} after the last of them; the part returned, from
         * now to the end, carries the rest of the stream from there (filled by the caller).
         */
        Slot cutAt(long nowNs) {
            long bitNanos = fromCarried + bitsPerSecond * (nowNs - startNs);
            long whole = Math.min(bitNanos / BYTE, toOffset - fromOffset);
            Slot rest = new Slot(nowNs, endNs);
            rest.fromOffset = fromOffset + whole;
            rest.fromCarried = whole == toOffset - fromOffset ? 0 : bitNanos - whole * BYTE;
            endNs = nowNs;
            toOffset = fromOffset + whole;
            dueNs = Math.min(dueNs, lastOnTheAir(whole) + delayNs);
            return rest;
        }

        /** When the last of its first {@code bytes} bytes is on the air. */
        long lastOnTheAir(long bytes) {
            long needed = Math.max(0, bytes * BYTE - fromCarried);
            return Math.min(endNs, startNs + (needed + bitsPerSecond - 1) / bitsPerSecond);
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
            arrived |= granted == received;
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
        for (Slot slot : slots) {
            if (slot.dueNs - nowNs > 0) {
                next = slot.dueNs - nowNs;
                break;
            }
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
     * Counts again, at the present rate and delay, the grants not yet over (after a change), or
     * fills their time to spare (bytes read while every byte held had its grant), takes grants
     * while it is this direction's turn, then marks what has fallen due.
     */
    private void pump(long nowNs) {
        if (changed) {
            changed = false;
            arrived = false;
            recount(nowNs);
        } else if (arrived) {
            arrived = false;
            refill(nowNs);
        }
        while (granted < received && (!anyGrant || lastStartNs - nowNs <= LOOKAHEAD_NS)) {
            Airtime.Grant grant = hop.grant(nanosFor(received - granted), nowNs);
            Slot slot = new Slot(grant.startNs(), grant.endNs());
            fill(slot);
            slots.addLast(slot);
            lastStartNs = slot.startNs;
            anyGrant = true;
        }
        for (Slot slot : slots) { // in order: a byte waits for those before it
            if (slot.dueNs - nowNs > 0) {
                break;
            }
            released = Math.max(released, slot.toOffset);
        }
        while (!slots.isEmpty() && slots.peekFirst().dueNs - nowNs <= 0 && slots.peekFirst().endNs - nowNs <= 0) {
            slots.pollFirst(); // kept while on the air, for a change to cut
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

    /**
     * What {@code slot} carries at the present rate, from where the stream stands, and when it is
     * due: when its last byte is on the air (its end, or sooner when it carries every byte held
     * with time to spare, a grant booked before a rate was raised), plus the delay.
     */
    private void fill(Slot slot) {
        slot.fromOffset = granted;
        slot.fromCarried = carried;
        long bitNanos = carried + bitsPerSecond * (slot.endNs - slot.startNs);
        long bytes = Math.min(bitNanos / BYTE, received - granted);
        granted += bytes;
        carried = granted == received ? 0 : bitNanos - bytes * BYTE;
        slot.bitsPerSecond = bitsPerSecond;
        slot.delayNs = delayMs * 1_000_000L;
        slot.toOffset = granted;
        slot.dueNs = slot.lastOnTheAir(bytes) + slot.delayNs;
    }

    /**
     * After a change of rate or delay: the grant on the air at {@code nowNs} is cut at now (what
     * it carried until then stays, due as it was), and from now on it and the grants booked but
     * not yet begun carry what the present rate puts in them, due after the present delay. Those
     * that have ended keep theirs.
     */
    private void recount(long nowNs) {
        List<Slot> all = new ArrayList<>(slots);
        int first = firstNotOver(all, nowNs);
        if (first == all.size()) {
            return;
        }
        if (all.get(first).startNs - nowNs < 0) {
            first = cut(all, first, nowNs);
        }
        granted = all.get(first).fromOffset;
        carried = all.get(first).fromCarried;
        fillFrom(all, first);
    }

    /**
     * Bytes read while every byte held had its grant: the time the grants not yet over have to
     * spare after the last byte held (and after now) carries them, so that grants booked at a
     * rate since raised carry the raised rate's bytes, and no byte held waits for those read after it.
     */
    private void refill(long nowNs) {
        List<Slot> all = new ArrayList<>(slots);
        int first = firstNotOver(all, nowNs);
        int holder = -1; // the last grant not yet over that carries bytes: those held last
        for (int i = first; i < all.size(); i++) {
            if (all.get(i).toOffset > all.get(i).fromOffset) {
                holder = i;
            }
        }
        if (holder >= 0) {
            Slot slot = all.get(holder);
            long spareFrom = Math.max(nowNs, slot.lastOnTheAir(slot.toOffset - slot.fromOffset));
            first = spareFrom - slot.endNs < 0 ? cut(all, holder, spareFrom) : holder + 1;
        } else if (first < all.size() && all.get(first).startNs - nowNs < 0) {
            first = cut(all, first, nowNs);
        }
        if (first < all.size()) {
            fillFrom(all, first); // from granted == what was held, nothing carried
        }
    }

    /** The index of the first of {@code all} not over at {@code nowNs}; its size if none. */
    private static int firstNotOver(List<Slot> all, long nowNs) {
        int first = all.size();
        while (first > 0 && all.get(first - 1).endNs - nowNs > 0) {
            first--;
        }
        return first;
    }

    /** Cuts {@code all}'s slot at {@code index} at {@code atNs}, the part after it put in the slots next: @return its index */
    private int cut(List<Slot> all, int index, long atNs) {
        all.add(index + 1, all.get(index).cutAt(atNs));
        slots.clear();
        slots.addAll(all);
        return index + 1;
    }

    /** Fills {@code all}'s slots from {@code index} on, from where the stream stands. */
    private void fillFrom(List<Slot> all, int index) {
        for (int i = index; i < all.size(); i++) {
            fill(all.get(i));
        }
    }
}
