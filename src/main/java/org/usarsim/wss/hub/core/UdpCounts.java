package org.usarsim.wss.hub.core;

import java.util.concurrent.atomic.LongAdder;

/**
 * What one direction of a pair's fixed UDP ports did (docs/fixed-ports.md): datagrams and bytes
 * sent to the receiving robot, and the datagrams that were not: dropped because the pair was
 * broken, dropped because a shaped queue was full, lost to the signal (wss.shaping.loss). Added by
 * the relays' threads without a lock, read by whoever samples. A pair's counts are the sum of its
 * fixed UDP ports': each relay counts its own port ({@link #of}), which adds to the pair's too.
 */
public final class UdpCounts {

    /** The five figures at one reading. */
    public record Reading(long datagrams, long bytes, long droppedBroken, long droppedQueue, long lost) {

        public static final Reading NONE = new Reading(0, 0, 0, 0, 0);

        /** Whether nothing was ever counted: no fixed UDP port carried anything for the pair this way. */
        public boolean none() {
            return datagrams == 0 && droppedBroken == 0 && droppedQueue == 0 && lost == 0;
        }
    }

    private final LongAdder datagrams = new LongAdder();
    private final LongAdder bytes = new LongAdder();
    private final LongAdder droppedBroken = new LongAdder();
    private final LongAdder droppedQueue = new LongAdder();
    private final LongAdder lost = new LongAdder();
    /** The pair's counts, which these (one fixed port's) add to; null for the pair's own. */
    private final UdpCounts whole;

    /** A pair's counts one way. */
    public UdpCounts() {
        this(null);
    }

    private UdpCounts(UdpCounts whole) {
        this.whole = whole;
    }

    /** One fixed port's counts one way, each added to {@code whole} (the pair's) as well. */
    public static UdpCounts of(UdpCounts whole) {
        return new UdpCounts(whole);
    }

    /** A datagram of {@code length} bytes was sent to the receiving robot. */
    public void sent(int length) {
        datagrams.increment();
        bytes.add(length);
        if (whole != null) {
            whole.sent(length);
        }
    }

    /** A datagram was dropped: the pair was broken (or forced down). */
    public void droppedBroken() {
        droppedBroken.increment();
        if (whole != null) {
            whole.droppedBroken();
        }
    }

    /** A datagram was dropped: the shaped queue had no room for it. */
    public void droppedQueue() {
        droppedQueue.increment();
        if (whole != null) {
            whole.droppedQueue();
        }
    }

    /** Datagrams lost to the signal. */
    public void lost(long count) {
        lost.add(count);
        if (whole != null) {
            whole.lost(count);
        }
    }

    public Reading read() {
        return new Reading(datagrams.sum(), bytes.sum(), droppedBroken.sum(), droppedQueue.sum(), lost.sum());
    }
}
