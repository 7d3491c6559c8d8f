package org.usarsim.wss.shaping;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.HashMap;
import java.util.Map;

/**
 * The radios' ledger: when each robot's radio is on the air. Every robot has one radio with one
 * second of airtime per second, shared by all its links, sending and receiving alike: n bytes
 * on a link at rate R keep the sender's radio and the receiver's radio busy for n x 8 / R
 * seconds (half duplex), starting when both are free. A relay that receives and sends again pays
 * twice.
 *
 * <p>A link direction asks for its bytes' airtime through its {@link Hop}, one {@link Grant} at
 * a time, each of at most {@link #QUANTUM_NS} of airtime, whatever the rate (a byte at 1 bit/s
 * lasts 8 s: it is carried over 4,000 grants, and the links sharing its radio keep their turns).
 * A grant takes the first time both radios are free for it, a gap between reservations included,
 * but never before its direction's last grant (its bytes keep their order). So when every busy
 * direction books the same few grants ahead (as {@link ShapedFlow} does), the directions sharing
 * a radio take turns in equal slices of TIME, not of bytes: a slow far link and a fast near one
 * each get their share, and neither starves. A radio that has been idle starts the next grant at
 * once; idle time is not saved up.
 *
 * <p>A direction whose robot's program has not yet taken what its radio received (the robot's
 * socket is full: a relay whose next hop is slower) does not take turns: it asks for an
 * {@link Hop#idleGrant}, airtime both radios have free now or between reservations already made,
 * which no direction taking turns has asked for (docs/shaping.md, "A target behind"). A relay's
 * incoming hop thus fills the time its outgoing hop waits for the next relay's radio, as a
 * radio's receive buffer would, instead of taking that hop's turns.
 *
 * <p>{@link #unshared()} is the ledger without a shared medium: each hop has its own radio, so
 * each direction is limited only by its own rate.
 *
 * <p>Thread-safe (one lock for the whole ledger, held for a few arithmetic steps per grant) and
 * pure in time: it never reads a clock; every method is given the time, {@code nowNs} as
 * {@link System#nanoTime()} says it (any long, negative ones included).
 */
public final class Airtime {

    /**
     * The most airtime one grant takes, 2 ms: a few kilobytes at 802.11g rates (13,500 bytes at
     * 54 Mbit/s, 1,500 at 6 Mbit/s). Short enough that directions sharing a radio interleave
     * finely, long enough that a link thread wakes at most about 500 times a second per direction.
     */
    public static final long QUANTUM_NS = 2_000_000;

    /** The window over which {@link #inUse} measures: the last second. */
    public static final long WINDOW_NS = 1_000_000_000;

    /** The ledger's resolution: the window is kept as 100 slices of 10 ms. */
    private static final long SLICE_NS = 10_000_000;
    private static final int SLICES = (int) (WINDOW_NS / SLICE_NS);

    /** The shortest gap an idle grant takes (unless it asks for less): 50 us. */
    static final long MIN_IDLE_NS = 50_000;

    /**
     * Airtime granted to one direction: its radio and its peer's are on the air for it from
     * {@code startNs} (never before the time asked) to {@code endNs}, at most {@link #QUANTUM_NS}.
     * What the slot carries is the direction's to say ({@link ShapedFlow}): bytes, or part of one.
     */
    public record Grant(long startNs, long endNs) {
    }

    private final boolean shared;
    private final Map<String, Radio> radios = new HashMap<>();

    private Airtime(boolean shared) {
        this.shared = shared;
    }

    /** A ledger where each robot's radio is shared by all its links ({@code wss.shaping.airtime=true}). */
    public static Airtime shared() {
        return new Airtime(true);
    }

    /** A ledger where each direction only has its own rate ({@code wss.shaping.airtime=false}). */
    public static Airtime unshared() {
        return new Airtime(false);
    }

    /** Whether robots' radios are shared by their links. */
    public boolean isShared() {
        return shared;
    }

    /**
     * The way over the air for one direction of one link, from robot {@code from} to robot
     * {@code to}; {@link Hop#close()} it when the link ends.
     */
    public synchronized Hop open(String from, String to, long nowNs) {
        if (!shared) {
            Radio own = new Radio(nowNs, false);
            return new Hop(own, own);
        }
        radios.values().removeIf(radio -> radio.hops == 0 && nowNs - radio.busyUntil >= WINDOW_NS);
        Radio sender = radios.computeIfAbsent(from, name -> new Radio(nowNs, true));
        Radio receiver = radios.computeIfAbsent(to, name -> new Radio(nowNs, true));
        sender.hops++;
        if (receiver != sender) {
            receiver.hops++;
        }
        return new Hop(sender, receiver);
    }

    /**
     * The fraction (0 to 1) of the last second that {@code robot}'s radio was on the air, sending
     * or receiving: 0 for a robot it does not know; NaN for an {@link #unshared()} ledger, where
     * robots have no shared radio to measure.
     */
    public synchronized double inUse(String robot, long nowNs) {
        if (!shared) {
            return Double.NaN;
        }
        Radio radio = radios.get(robot);
        return radio == null ? 0 : radio.inUse(nowNs);
    }

    /** One direction of one link: the radio it sends from and the one it sends to. */
    public final class Hop {
        private final Radio sender;
        private final Radio receiver;
        private boolean closed;
        /** Where this direction's last grant ends: its next starts no earlier, so its bytes keep their order. */
        private long lastEnd = Long.MIN_VALUE;
        private boolean granted;
        private long idleFrom;

        private Hop(Radio sender, Radio receiver) {
            this.sender = sender;
            this.receiver = receiver;
        }

        /**
         * A slot of {@code nanos} of airtime (1 to {@link #QUANTUM_NS}), starting at the first time
         * both radios are free for that long (a gap between their reservations too), not before
         * {@code nowNs} nor before this direction's last grant ends. Both radios are then busy until the slot's end.
         * Slots are measured in time, not bytes, so a slow link takes no more than its turn of a
         * shared radio however long one of its bytes lasts: it carries a byte over as many slots
         * as the byte needs.
         *
         * @throws IllegalStateException once the hop is closed
         */
        public Grant grant(long nanos, long nowNs) {
            checkLength(nanos);
            synchronized (Airtime.this) {
                checkOpen();
                long from = from(nowNs);
                long start = sender.measured ? earliestFree(from, nanos) : latest(from, sender.busyUntil);
                return book(start, start + nanos, nowNs);
            }
        }

        /**
         * Airtime nobody has asked for, for a direction whose robot's program has not yet taken what
         * the radio received (a radio's receive buffer): up to {@code nanos} (1 to
         * {@link #QUANTUM_NS}) in the first gap, not before {@code nowNs} nor this direction's last
         * grant, that both radios have free either now or between reservations already made
         * (shortened to fit the gap; a gap shorter than {@link #MIN_IDLE_NS} is skipped unless
         * that is all it asks); null when the first such time is later than now with nothing
         * reserved after it, a time the directions taking turns may yet want: {@link #idleFrom()}
         * then says when to ask again. So it never delays a grant a direction asked for in turn.
         * Without shared airtime it is any grant.
         */
        public Grant idleGrant(long nanos, long nowNs) {
            checkLength(nanos);
            synchronized (Airtime.this) {
                if (!sender.measured) {
                    return grant(nanos, nowNs);
                }
                checkOpen();
                long start = earliestFree(from(nowNs), Math.min(nanos, MIN_IDLE_NS));
                long end = start + nanos;
                boolean gap = false;
                for (Radio radio : new Radio[] {sender, receiver}) {
                    if (radio.reservedAfter(start)) {
                        gap = true;
                        long next = radio.nextStart(start);
                        end = next - end < 0 ? next : end;
                    }
                }
                if (!gap && start - nowNs > 0) {
                    idleFrom = start;
                    return null;
                }
                return book(start, end, nowNs);
            }
        }

        private static void checkLength(long nanos) {
            if (nanos < 1 || nanos > QUANTUM_NS) {
                throw new IllegalArgumentException("a grant of 1 to " + QUANTUM_NS + " ns, not " + nanos);
            }
        }

        private void checkOpen() {
            if (closed) {
                throw new IllegalStateException("this hop is closed");
            }
        }

        /** The earliest a grant of this direction starts: now, and not before its last grant ends. */
        private long from(long nowNs) {
            return granted ? latest(nowNs, lastEnd) : nowNs;
        }

        /** Both radios on the air for this direction from {@code start} to {@code end}. */
        private Grant book(long start, long end, long nowNs) {
            granted = true;
            lastEnd = end;
            sender.reserve(start, end, nowNs);
            if (receiver != sender) {
                receiver.reserve(start, end, nowNs);
            }
            return new Grant(start, end);
        }

        /** After {@link #idleGrant} gave none: when both radios are next free with nothing reserved after. */
        public long idleFrom() {
            synchronized (Airtime.this) {
                return idleFrom;
            }
        }

        /** The earliest start, not before {@code from}, of {@code nanos} free on both radios: the first idle gap of both. */
        private long earliestFree(long from, long nanos) {
            long start = from;
            while (true) {
                long moved = receiver.freeFrom(sender.freeFrom(start, nanos), nanos);
                if (moved == start) {
                    return start;
                }
                start = moved;
            }
        }

        /** Ends the hop: its robots' radios are forgotten once no hop uses them and their last second was idle. */
        public void close() {
            synchronized (Airtime.this) {
                if (!closed) {
                    closed = true;
                    sender.hops--;
                    if (receiver != sender) {
                        receiver.hops--;
                    }
                }
            }
        }
    }

    private static long latest(long a, long b) {
        return a - b >= 0 ? a : b;
    }

    /**
     * One radio: when it is free again, and (for a shared radio) how much of the last second it
     * was busy. Reserved airtime not yet past is kept as intervals (adjacent ones merged, so a busy
     * radio has one or two); what is past is added up in 10 ms slices of the last second.
     */
    private static final class Radio {
        long busyUntil;
        int hops;
        private final boolean measured;
        /** The reserved intervals, in order, none overlapping. */
        private final List<long[]> ahead = new ArrayList<>();
        private long settledNs;
        private final long[] sliceIndex = new long[SLICES];
        private final long[] sliceBusy = new long[SLICES];

        Radio(long nowNs, boolean measured) {
            this.busyUntil = nowNs;
            this.settledNs = nowNs;
            this.measured = measured;
            Arrays.fill(sliceIndex, Long.MIN_VALUE);
        }

        void reserve(long start, long end, long nowNs) {
            busyUntil = latest(busyUntil, end);
            if (!measured) {
                return;
            }
            settle(nowNs);
            int at = ahead.size();
            while (at > 0 && ahead.get(at - 1)[0] - start > 0) {
                at--;
            }
            long[] before = at > 0 ? ahead.get(at - 1) : null;
            long[] after = at < ahead.size() ? ahead.get(at) : null;
            if (before != null && before[1] == start) {
                before[1] = end;
                if (after != null && after[0] == end) {
                    before[1] = after[1];
                    ahead.remove(at);
                }
            } else if (after != null && after[0] == end) {
                after[0] = start;
            } else {
                ahead.add(at, new long[] {start, end});
            }
        }

        /** The earliest time, not before {@code from}, from which this radio is free for {@code nanos}. */
        long freeFrom(long from, long nanos) {
            long start = latest(from, settledNs); // what is settled is past: no grant goes back into it
            for (long[] interval : ahead) {
                if (interval[0] - (start + nanos) >= 0) {
                    break;
                }
                if (interval[1] - start > 0) {
                    start = interval[1];
                }
            }
            return start;
        }

        /** Whether a reservation starts at or after {@code time}. */
        boolean reservedAfter(long time) {
            return !ahead.isEmpty() && ahead.get(ahead.size() - 1)[0] - time >= 0;
        }

        /** The start of the first reservation at or after {@code time} (there is one: {@link #reservedAfter}). */
        long nextStart(long time) {
            for (long[] interval : ahead) {
                if (interval[0] - time >= 0) {
                    return interval[0];
                }
            }
            throw new IllegalStateException("nothing reserved after " + time);
        }

        double inUse(long nowNs) {
            settle(nowNs);
            long newest = Math.floorDiv(nowNs, SLICE_NS);
            long oldest = newest - SLICES + 1;
            long busy = 0;
            for (long index = oldest; index <= newest; index++) {
                int slot = (int) Math.floorMod(index, SLICES);
                if (sliceIndex[slot] == index) {
                    busy += sliceBusy[slot];
                }
            }
            double span = nowNs - oldest * SLICE_NS;
            return Math.min(1, busy / span);
        }

        /** Moves the reserved airtime before {@code nowNs} into the slices. */
        private void settle(long nowNs) {
            if (nowNs - settledNs <= 0) {
                return;
            }
            while (!ahead.isEmpty()) {
                long[] interval = ahead.get(0);
                long from = latest(interval[0], settledNs);
                long to = interval[1] - nowNs <= 0 ? interval[1] : nowNs;
                if (to - from > 0) {
                    count(from, to);
                }
                if (interval[1] - nowNs > 0) {
                    break;
                }
                ahead.remove(0);
            }
            settledNs = nowNs;
        }

        private void count(long from, long to) {
            long start = latest(from, to - WINDOW_NS - SLICE_NS);
            for (long index = Math.floorDiv(start, SLICE_NS); index * SLICE_NS - to < 0; index++) {
                long sliceStart = index * SLICE_NS;
                long overlap = Math.min(to, sliceStart + SLICE_NS) - Math.max(start, sliceStart);
                int slot = (int) Math.floorMod(index, SLICES);
                if (sliceIndex[slot] != index) {
                    sliceIndex[slot] = index;
                    sliceBusy[slot] = 0;
                }
                sliceBusy[slot] += overlap;
            }
        }
    }
}
