package org.usarsim.wss.shaping;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.LongSupplier;
import java.util.zip.CRC32;

/**
 * Shaped directions driven the way a link thread drives one, on a clock the test moves: at each
 * step every direction writes what is due to its target, then reads from its source while it has
 * room, then the clock jumps to the next time any direction has something to do. Checked, sources
 * send a known stream (byte i is {@link #byteAt}(i)) and targets check every byte they get
 * against it; unchecked, they only count (the long runs at high rates).
 */
final class SimulatedLinks {

    /** Where a direction's bytes come from. */
    interface Source {
        /** How many bytes are there to read now (Long.MAX_VALUE: as many as wanted). */
        long available();
    }

    /** One direction: its flow, what feeds it, and the target's count and checks. */
    final class Lane implements OpenTarget {
        final ShapedFlow flow;
        final Source source;
        final Random sizes;
        final int chunkSize;
        /** Bytes read from the source (the offset of the next byte read). */
        long read;
        /** Bytes that reached the target. */
        long delivered;
        /** Bytes the target may still take this step; Long.MAX_VALUE: all. */
        long acceptable = Long.MAX_VALUE;
        /** How many bytes the target takes at each step (a full socket takes few or none); null: all. */
        LongSupplier takes;
        final CRC32 sent = new CRC32();
        final CRC32 got = new CRC32();
        long mostHeld;
        /** What an unchecked source reads into, again and again. */
        private final ByteBuffer blank;

        Lane(ShapedFlow flow, Source source, int chunkSize, Random sizes) {
            this.flow = flow;
            this.source = source;
            this.chunkSize = chunkSize;
            this.sizes = sizes;
            this.blank = ByteBuffer.allocate(chunkSize);
        }

        /** A turn of its link's thread: writes what is due (what the target takes), then reads what fits. */
        void turn() {
            acceptable = takes == null ? Long.MAX_VALUE : takes.getAsLong();
            try {
                flow.writeTo(this, now);
            } catch (IOException e) {
                throw new AssertionError(e);
            }
            readWhatFits();
        }

        void readWhatFits() {
            while (flow.room() > 0 && source.available() - read > 0) {
                int most = sizes == null ? chunkSize : 1 + sizes.nextInt(chunkSize);
                int count = (int) Math.min(Math.min(flow.room(), most), source.available() - read);
                ByteBuffer chunk = checked ? ByteBuffer.allocate(count) : blank.clear().limit(count);
                if (checked) {
                    for (int i = 0; i < count; i++) {
                        chunk.put(byteAt(read + i));
                    }
                    chunk.flip();
                    sent.update(chunk.array(), 0, count);
                }
                flow.accept(chunk, now);
                read += count;
                mostHeld = Math.max(mostHeld, flow.held());
            }
        }

        @Override
        public int write(ByteBuffer bytes) {
            int count = (int) Math.min(bytes.remaining(), acceptable);
            if (!checked) {
                bytes.position(bytes.position() + count);
                delivered += count;
            }
            for (int i = 0; checked && i < count; i++) {
                byte b = bytes.get();
                if (b != byteAt(delivered)) {
                    throw new AssertionError("byte " + delivered + " is wrong: lost, reordered or duplicated");
                }
                got.update(b);
                delivered++;
            }
            if (acceptable != Long.MAX_VALUE) {
                acceptable -= count;
            }
            return count;
        }
    }

    /** How soon a direction whose target took less than was due tries again (a wake-up for OP_WRITE). */
    private static final long RETRY_NS = 100_000;

    final Airtime airtime;
    final boolean checked;
    final List<Lane> lanes = new ArrayList<>();
    long now;

    SimulatedLinks(Airtime airtime, long startNs, boolean checked) {
        this.airtime = airtime;
        this.now = startNs;
        this.checked = checked;
    }

    /** A direction from robot {@code from} to {@code to} fed by {@code source}, reading whole chunks. */
    Lane add(String from, String to, long bitsPerSecond, int delayMs, int chunkSize, Source source) {
        return add(from, to, bitsPerSecond, delayMs, chunkSize, source, null);
    }

    /** As {@link #add}, reading chunks of random sizes from 1 to {@code chunkSize} with {@code sizes}. */
    Lane add(String from, String to, long bitsPerSecond, int delayMs, int chunkSize, Source source, Random sizes) {
        return add(from, to, bitsPerSecond, delayMs, ShapingConfig.DEFAULT_QUEUE_MS, chunkSize, source, sizes);
    }

    /** A lane with a queue of {@code queueMs} rather than the default. */
    Lane add(String from, String to, long bitsPerSecond, int delayMs, int queueMs, int chunkSize, Source source, Random sizes) {
        ShapedFlow flow = new ShapedFlow(airtime.open(from, to, now), bitsPerSecond, delayMs, queueMs);
        Lane lane = new Lane(flow, source, chunkSize, sizes);
        lanes.add(lane);
        return lane;
    }

    /** A source that always has more. */
    static Source endless() {
        return () -> Long.MAX_VALUE;
    }

    /** A source of {@code bytes} bytes in all. */
    static Source finite(long bytes) {
        return () -> bytes;
    }

    /** A source that has what {@code lane} delivered so far: a robot sending on what it receives. */
    Source relayOf(Lane lane) {
        return () -> lane.delivered;
    }

    /** Runs the directions until {@code endNs}, then writes what is due then. */
    void runUntil(long endNs) {
        runUntil(endNs, () -> false);
    }

    /**
     * Runs the directions until {@code lane} has delivered {@code bytes} in all, at most until
     * {@code endNs}. @return the time it had, or -1
     */
    long runUntilDelivered(Lane lane, long bytes, long endNs) {
        runUntil(endNs, () -> lane.delivered >= bytes);
        return lane.delivered >= bytes ? now : -1;
    }

    /** Runs the directions until {@code endNs}, or until a step after which {@code enough} holds. */
    private void runUntil(long endNs, java.util.function.BooleanSupplier enough) {
        while (true) {
            step();
            if (enough.getAsBoolean()) {
                return;
            }
            long next = Long.MAX_VALUE;
            for (Lane lane : lanes) {
                next = Math.min(next, lane.flow.nanosUntilNext(now));
                if (lane.flow.due(now) > 0) {
                    next = Math.min(next, RETRY_NS);
                }
            }
            if (next == Long.MAX_VALUE || endNs - now <= next) {
                break;
            }
            now += Math.max(1, next);
        }
        now = endNs;
        step();
    }

    /** Moves the clock by {@code nanos}, running everything due on the way. */
    void runFor(long nanos) {
        runUntil(now + nanos);
    }

    private void step() {
        for (Lane lane : lanes) {
            lane.turn();
        }
    }

    /** The byte at offset {@code i} of every source's stream: a scrambled function of i. */
    static byte byteAt(long i) {
        return (byte) ((i * 0x9E3779B97F4A7C15L) >>> 56);
    }
}
