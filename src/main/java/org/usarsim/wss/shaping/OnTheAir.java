package org.usarsim.wss.shaping;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * The air, a shaped direction's stage between its queue and what follows the air
 * (docs/shaping.md, "Stages"): the grants its {@link Airtime.Hop} gives it at the link's rate,
 * what each carries of the bytes queued ({@link HeldBytes}), and when those may be written, as
 * the stage after the air ({@link AfterAir}) says from when the last of them is on the air.
 *
 * <p>Bytes go on the air in order, lazily: whenever the direction's last grant starts within
 * {@link #LOOKAHEAD_NS}, the bytes not yet on the air ask the hop for the next grant, at the rate
 * the link has at that moment. So a busy direction holds one grant on the air and books at most
 * two quanta ahead, and directions sharing a radio take turns; while the target is behind (the
 * last write left bytes due, {@link #targetTookAll}), it asks only for airtime nobody asked for
 * ({@link Airtime.Hop#idleGrant}), and when none is left, asks again when the hop says. A rate change reaches the link at
 * its next step: the grant on the air carries at the new rate from the change on, the grants
 * booked ahead carry at the new rate, and every later grant is asked at it; the grants keep
 * their airtime. A grant's bytes are off the air once its last byte is on the air (its end, or
 * sooner when it carries every byte held with time to spare); a change of what follows the air
 * (the delay) applies to the grants not yet over. A grant's bytes are written in order: after
 * those of the grants before it.
 *
 * <p>Used by one thread; it never reads a clock nor blocks.
 */
final class OnTheAir {

    /**
     * How far ahead a busy direction books its grants: the next is booked once the last one
     * starts within two quanta (4 ms), so that a link thread woken a few milliseconds late (a
     * busy machine) finds its radio's next grants already booked instead of an idle radio and
     * lost airtime.
     */
    static final long LOOKAHEAD_NS = 2 * Airtime.QUANTUM_NS;

    /** One byte in bit x nanoseconds: a grant of d ns at R bit/s carries R x d of them. */
    private static final long BYTE = 8_000_000_000L;

    private final Airtime.Hop hop;
    /** What it carries: the queue's bytes from offset {@code granted} on. */
    private final HeldBytes queue;
    private final AfterAir afterAir;
    private long bitsPerSecond;
    /** Grants whose bytes are not yet due or that are not yet over, in order. */
    private final ArrayDeque<Slot> slots = new ArrayDeque<>();
    // Offsets in the queue's stream: received >= granted >= released >= written.
    private long granted;
    private long released;
    /** The part of byte {@code granted} already on the air, in bit x nanoseconds (below {@link #BYTE}). */
    private long carried;
    private long lastStartNs;
    private boolean anyGrant;
    /** The rate or what follows the air changed since the last step: the grants not yet over are counted again. */
    private boolean changed;
    /**
     * The target's program has not taken every byte due (the last write left some): the radio's
     * receive buffer holds them, and the air takes only airtime nobody asked for
     * ({@link Airtime.Hop#idleGrant}) until it has.
     */
    private boolean behind;
    /** While behind, no idle airtime was left: the next is asked for at {@link #idleRetryNs}. */
    private boolean waitingIdle;
    private long idleRetryNs;
    /** Bytes were read since the last step while every byte held had its grant: the time booked to spare carries them. */
    private boolean arrived;

    /**
     * A grant of airtime, or its part from a cut on, and what it carries: the stream from
     * {@code fromOffset} (with {@code fromCarried} of the next byte already on the air before it)
     * to {@code toOffset}, at {@code bitsPerSecond}, due at {@code dueNs} ({@code afterAirNs}
     * after its last byte is on the air, as the stage after the air said).
     */
    private static final class Slot {
        final long startNs;
        long endNs;
        long fromOffset;
        long fromCarried;
        long bitsPerSecond;
        long afterAirNs;
        long toOffset;
        long dueNs;

        Slot(long startNs, long endNs) {
            this.startNs = startNs;
            this.endNs = endNs;
        }

        /**
         * Cuts it at {@code nowNs}, while it is on the air: this part keeps the bytes whole on
         * the air by then, due {@link #afterAirNs} after the last of them; the part returned, from
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
            dueNs = Math.min(dueNs, lastOnTheAir(whole) + afterAirNs);
            return rest;
        }

        /** When the last of its first {@code bytes} bytes is on the air. */
        long lastOnTheAir(long bytes) {
            long needed = Math.max(0, bytes * BYTE - fromCarried);
            return Math.min(endNs, startNs + (needed + bitsPerSecond - 1) / bitsPerSecond);
        }
    }

    /** The air of a direction through {@code hop} (it owns it), carrying {@code queue}'s bytes, followed by {@code afterAir}. */
    OnTheAir(Airtime.Hop hop, HeldBytes queue, AfterAir afterAir, long bitsPerSecond) {
        this.hop = hop;
        this.queue = queue;
        this.afterAir = afterAir;
        this.bitsPerSecond = bitsPerSecond;
        this.changed = true;
    }

    long rate() {
        return bitsPerSecond;
    }

    /** The rate from now on, for the bytes not yet on the air. */
    void setRate(long bitsPerSecond) {
        changed |= bitsPerSecond != this.bitsPerSecond;
        this.bitsPerSecond = bitsPerSecond;
    }

    /** What follows the air changed (a new delay): the grants not yet over are due as it now says. */
    void afterAirChanged() {
        changed = true;
    }

    /** The queue is about to take bytes read (call before it takes them). */
    void arriving() {
        arrived |= granted == queue.received();
    }

    /** Takes the time: grants asked while it is this direction's turn, what fell due marked. */
    void step(long nowNs) {
        pump(nowNs);
    }

    /** The offset in the queue's stream up to which its bytes may be written at {@code nowNs}. */
    long released(long nowNs) {
        pump(nowNs);
        return released;
    }

    /**
     * How long from {@code nowNs} until the air has something new to do: bytes falling due, or
     * its turn to ask for more airtime; 0 if that is now, {@link Long#MAX_VALUE} if nothing is
     * scheduled (it carries nothing, or only bytes already due).
     */
    long nanosUntilNext(long nowNs) {
        pump(nowNs);
        long next = Long.MAX_VALUE;
        for (Slot slot : slots) {
            if (slot.dueNs - nowNs > 0) {
                next = slot.dueNs - nowNs;
                break;
            }
        }
        if (granted < queue.received()) {
            long turn = behind && waitingIdle ? idleRetryNs : lastStartNs - LOOKAHEAD_NS;
            next = Math.min(next, Math.max(0, turn - nowNs));
        }
        return next;
    }

    /** Whether the target took every byte due at the last write: if not, the air takes only idle airtime until it does. */
    void targetTookAll(boolean all) {
        behind = !all;
        if (all) {
            waitingIdle = false;
        }
    }

    /** Ends the hop. */
    void close() {
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
        while (granted < queue.received() && (!anyGrant || lastStartNs - nowNs <= LOOKAHEAD_NS)
                && !(behind && waitingIdle && idleRetryNs - nowNs > 0)) {
            long nanos = nanosFor(queue.received() - granted);
            Airtime.Grant grant = behind ? hop.idleGrant(nanos, nowNs) : hop.grant(nanos, nowNs);
            if (grant == null) {
                waitingIdle = true;
                idleRetryNs = hop.idleFrom();
                break;
            }
            waitingIdle = false;
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
     * with time to spare, a grant booked before a rate was raised), as the stage after the air says.
     */
    private void fill(Slot slot) {
        long received = queue.received();
        slot.fromOffset = granted;
        slot.fromCarried = carried;
        long bitNanos = carried + bitsPerSecond * (slot.endNs - slot.startNs);
        long bytes = Math.min(bitNanos / BYTE, received - granted);
        granted += bytes;
        carried = granted == received ? 0 : bitNanos - bytes * BYTE;
        slot.bitsPerSecond = bitsPerSecond;
        slot.toOffset = granted;
        long offAirNs = slot.lastOnTheAir(bytes);
        slot.dueNs = afterAir.dueAt(offAirNs);
        slot.afterAirNs = slot.dueNs - offAirNs;
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
