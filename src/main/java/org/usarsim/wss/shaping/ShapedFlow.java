package org.usarsim.wss.shaping;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.WritableByteChannel;

/**
 * One direction of one shaped link, as the link's loop asks it ({@link Pacing}): the bytes read
 * from one robot and not yet written to the other, and when each may be written. It is its
 * stages, in the order the bytes pass them (docs/shaping.md, "Stages"): the queue
 * ({@link HeldBytes}, at most {@link #capacity()}), the air ({@link OnTheAir}: grants of the
 * robots' radios at the link's rate) and what follows the air ({@link AfterAir}: the
 * {@link Delay}). The link's thread drives it, telling it the time at every step: it
 * {@link #accept}s what it read (at most {@link #room()}), {@link #writeTo}s the target what is
 * due, and waits at most {@link #nanosUntilNext} before asking again. A chunk read at t over an
 * idle radio is due at t + its bytes x 8 / rate + the delay. A new rate or delay
 * ({@link #setConditions}) reaches the bytes not yet on the air at the next step.
 *
 * <p>Nothing is lost, reordered or duplicated: shaping only changes when bytes are written. The
 * memory is bounded by {@link #capacity()}: rate x (delay + queue), the queue
 * ({@code wss.shaping.queueMs}, 20 ms by default) being what a radio's queue would hold; a
 * direction that holds that much reads no more, and TCP's back-pressure reaches the sender.
 *
 * <p>Used by one thread; it never reads a clock nor blocks.
 */
public final class ShapedFlow {

    /** The least a direction may hold whatever its rate: one frame's payload (so that a link at 1 bit/s still reads). */
    public static final int MIN_HELD = 1500;

    private final int queueMs;
    /** The stages, in the order bytes pass them: the queue, the air, the delay (and what may follow it). */
    private final HeldBytes queue = new HeldBytes();
    private final OnTheAir air;
    private final Delay delay;
    /** The delay's jitter (none: 0 ms), the stage after the delay. */
    private final Jitter jitter;
    private final AfterAir afterAir;
    private long capacity;

    /**
     * A direction that sends through {@code hop} at {@code bitsPerSecond} with {@code delayMs}
     * of delay and a queue of {@code queueMs} ({@code wss.shaping.queueMs}); it owns the hop and closes it.
     */
    public ShapedFlow(Airtime.Hop hop, long bitsPerSecond, int delayMs, int queueMs) {
        this(hop, bitsPerSecond, delayMs, queueMs, null);
    }

    /**
     * As the other, with a jitter after the delay ({@code jitterMs}, from now on as
     * {@link #setConditions(long, int, int)} says), drawn from {@code distribution} with a
     * generator seeded with {@code seed}; the bytes keep their order whatever it draws.
     */
    public ShapedFlow(Airtime.Hop hop, long bitsPerSecond, int delayMs, int jitterMs, int queueMs, JitterDistribution distribution,
            long seed) {
        this(hop, bitsPerSecond, delayMs, queueMs, null, new JitterStage(distribution, seed, jitterMs));
    }

    /** What a jitter stage is made of, before the delay it follows exists. */
    private record JitterStage(JitterDistribution distribution, long seed, int ms) {
        static final JitterStage NONE = new JitterStage(JitterDistribution.UNIFORM, 0, 0);
    }

    /**
     * As the other, with {@code next} after the delay if it is not null: another stage after the
     * air, such as a jitter (docs/shaping.md, "Stages"; none is in use yet).
     */
    ShapedFlow(Airtime.Hop hop, long bitsPerSecond, int delayMs, int queueMs, AfterAir next) {
        this(hop, bitsPerSecond, delayMs, queueMs, next, JitterStage.NONE);
    }

    private ShapedFlow(Airtime.Hop hop, long bitsPerSecond, int delayMs, int queueMs, AfterAir next, JitterStage jitterStage) {
        if (queueMs < ShapingConfig.MIN_QUEUE_MS || queueMs > ShapingConfig.MAX_QUEUE_MS) {
            throw new IllegalArgumentException("a queue of " + ShapingConfig.MIN_QUEUE_MS + " to " + ShapingConfig.MAX_QUEUE_MS
                    + " ms, not " + queueMs);
        }
        this.queueMs = queueMs;
        this.delay = new Delay(delayMs);
        this.jitter = new Jitter(delay, jitterStage.distribution(), jitterStage.seed(), jitterStage.ms());
        AfterAir delayed = delay.then(jitter);
        this.afterAir = next == null ? delayed : delayed.then(next);
        this.air = new OnTheAir(hop, queue, afterAir, bitsPerSecond);
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
        return capacity(bitsPerSecond, delayMs * 1_000_000L, queueMs);
    }

    /** As {@link #capacity(long, int, int)}, for stages after the air that hold bytes {@code afterAirNs}. */
    private static long capacity(long bitsPerSecond, long afterAirNs, int queueMs) {
        return Math.max(MIN_HELD, Bitrate.bytesIn(afterAirNs + queueMs * 1_000_000L, bitsPerSecond));
    }

    /**
     * The link's rate and delay from now on (the pair's strength changed, or an operator forced
     * them): bytes not yet on the air go at the new rate and wait the new delay; the capacity follows.
     */
    public void setConditions(long bitsPerSecond, int delayMs) {
        setConditions(bitsPerSecond, delayMs, jitter.ms());
    }

    /** As {@link #setConditions(long, int)}, with the delay's jitter from now on, for the bytes not yet on the air. */
    public void setConditions(long bitsPerSecond, int delayMs, int jitterMs) {
        if (jitterMs < 0 || jitterMs > ShapingConfig.MAX_JITTER_MS) {
            throw new IllegalArgumentException("a jitter from 0 to " + ShapingConfig.MAX_JITTER_MS + " ms, not " + jitterMs);
        }
        if (bitsPerSecond < 1 || bitsPerSecond > Bitrate.MAX) {
            throw new IllegalArgumentException("a rate from 1 to " + Bitrate.MAX + " bit/s, not " + bitsPerSecond);
        }
        if (delayMs < ShapingConfig.MIN_DELAY_MS || delayMs > ShapingConfig.MAX_DELAY_MS) {
            throw new IllegalArgumentException("a delay from " + ShapingConfig.MIN_DELAY_MS + " to "
                    + ShapingConfig.MAX_DELAY_MS + " ms, not " + delayMs);
        }
        if (delayMs != delay.ms() || jitterMs != jitter.ms()) {
            delay.set(delayMs);
            jitter.set(jitterMs);
            air.afterAirChanged();
        }
        air.setRate(bitsPerSecond);
        this.capacity = capacity(bitsPerSecond, afterAir.holdsNs(), queueMs);
    }

    /** The rate in bit/s. */
    public long rate() {
        return air.rate();
    }

    /** The delay in milliseconds. */
    public int delayMs() {
        return delay.ms();
    }

    /** The delay's jitter in milliseconds. */
    public int jitterMs() {
        return jitter.ms();
    }

    /** The most bytes this direction holds at its present rate and delay. */
    public long capacity() {
        return capacity;
    }

    /** The bytes read and not yet written. */
    public long held() {
        return queue.held();
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
            air.arriving();
            queue.add(bytes);
        }
        air.step(nowNs);
    }

    /** How many bytes may be written at {@code nowNs}. */
    public long due(long nowNs) {
        return air.released(nowNs) - queue.written();
    }

    /**
     * Writes what is due at {@code nowNs} to {@code out}, in order, until all of it is written or
     * {@code out} takes no more (a non-blocking channel that is full). Until a write takes all
     * that is due again, the direction takes only airtime nobody asked for
     * ({@link Airtime.Hop#idleGrant}; docs/shaping.md, "A target behind").
     *
     * @return the bytes written
     */
    public int writeTo(WritableByteChannel out, long nowNs) throws IOException {
        long upTo = air.released(nowNs);
        int written = queue.writeTo(out, upTo);
        air.targetTookAll(queue.written() == upTo);
        return written;
    }

    /**
     * How long from {@code nowNs} until this direction has something new to do: bytes falling
     * due, or its turn to ask for more airtime; 0 if that is now, {@link Long#MAX_VALUE} if
     * nothing is scheduled (it holds nothing, or only bytes already due: those wait for the
     * target to take them, not for time).
     */
    public long nanosUntilNext(long nowNs) {
        return air.nanosUntilNext(nowNs);
    }

    /** Ends the direction's hop; what it still holds is dropped with it. */
    public void close() {
        air.close();
    }
}
