package org.usarsim.wss.hub.core;

import java.util.concurrent.atomic.LongAdder;

/**
 * What one direction of a pair's fixed UDP ports did (docs/fixed-ports.md): datagrams and bytes
 * sent to the receiving robot, and the datagrams that were not: dropped because the pair was
 * broken, dropped because a shaped queue was full, lost to the signal (wss.shaping.loss). Added by
 * the relays' threads without a lock, read by whoever samples.
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

    /** A datagram of {@code length} bytes was sent to the receiving robot. */
    public void sent(int length) {
        datagrams.increment();
        bytes.add(length);
    }

    /** A datagram was dropped: the pair was broken (or forced down). */
    public void droppedBroken() {
        droppedBroken.increment();
    }

    /** A datagram was dropped: the shaped queue had no room for it. */
    public void droppedQueue() {
        droppedQueue.increment();
    }

    /** Datagrams lost to the signal. */
    public void lost(long count) {
        lost.add(count);
    }

    public Reading read() {
        return new Reading(datagrams.sum(), bytes.sum(), droppedBroken.sum(), droppedQueue.sum(), lost.sum());
    }
}
