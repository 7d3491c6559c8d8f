package org.usarsim.wss.model.rfcomms;

import java.util.ArrayDeque;

/**
 * RFComms' capacity, one radio one way: what it sent (or received) in the last second, and whether
 * a message more still fits. As RFComms: the messages older than 1 s before now leave the window;
 * a message is refused when the window's bits and its own exceed capacity x 1 s, and counted when
 * admitted. Used by one thread; the time comes in.
 */
final class CapacityWindow {

    /** RFComms' epoch: 1 s. */
    static final long WINDOW_NS = 1_000_000_000L;

    private record Sent(long atNs, long bytes) {
    }

    private final double capacity;
    private final ArrayDeque<Sent> sent = new ArrayDeque<>();
    private long bytes;

    /** A window for a radio of {@code capacity} bit/s. */
    CapacityWindow(double capacity) {
        this.capacity = capacity;
    }

    /** Whether a message of {@code size} bytes at {@code nowNs} fits (it is then counted). */
    boolean admit(long nowNs, long size) {
        while (!sent.isEmpty() && sent.peek().atNs() - (nowNs - WINDOW_NS) < 0) {
            bytes -= sent.poll().bytes();
        }
        if ((bytes + size) * 8.0 > capacity * (WINDOW_NS / 1e9)) {
            return false;
        }
        sent.add(new Sent(nowNs, size));
        bytes += size;
        return true;
    }

    /** The bytes in the window as last counted. */
    long bytes() {
        return bytes;
    }
}
