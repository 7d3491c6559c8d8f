package org.usarsim.wss.monitor;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Logger;

/**
 * The open event streams, at most {@code max} (a slot is taken before the stream is answered and
 * given back when its thread is done), and what was lost to the viewers that did not read: each
 * one cut is logged once and counted, with the events it did not get.
 */
final class Streams {

    private static final Logger LOG = Logger.getLogger(Streams.class.getName());

    private final int max;
    private final AtomicInteger slots = new AtomicInteger();
    private final AtomicInteger numbers = new AtomicInteger();
    private final List<EventStream> open = new CopyOnWriteArrayList<>();
    private final AtomicLong cut = new AtomicLong();
    private final AtomicLong dropped = new AtomicLong();

    Streams(int max) {
        this.max = max;
    }

    /** Takes a slot; false when {@code max} streams are open. */
    boolean reserve() {
        while (true) {
            int taken = slots.get();
            if (taken >= max) {
                return false;
            }
            if (slots.compareAndSet(taken, taken + 1)) {
                return true;
            }
        }
    }

    /** A slot's stream ended (or was never started). */
    void release(EventStream stream) {
        if (stream != null) {
            open.remove(stream);
        }
        slots.decrementAndGet();
    }

    /** The stream (its slot reserved) receives from now on; its thread starts. */
    void add(EventStream stream) {
        listen(stream);
        stream.start(numbers.incrementAndGet());
    }

    /** The stream receives from now on (its thread is {@link #add}'s to start). */
    void listen(EventStream stream) {
        open.add(stream);
    }

    boolean isEmpty() {
        return open.isEmpty();
    }

    /** Offers the event to every stream; one whose queue is full is cut. Never waits. */
    void publish(SseEvent event) {
        for (EventStream stream : open) {
            if (!stream.offer(event) && open.remove(stream)) {
                cut.incrementAndGet();
                dropped.addAndGet(stream.lostAtCut());
                LOG.warning("monitor: cut the event stream of " + stream.who() + ": it did not read " + EventStream.MAX_QUEUED
                        + " events or " + EventStream.MAX_QUEUED_BYTES / (1024 * 1024) + " MiB (it may reconnect)");
            }
        }
    }

    /** Ends every stream (the server stops). */
    void closeAll() {
        for (EventStream stream : open) {
            stream.close();
        }
        open.clear();
    }

    /** The streams open now (slots taken). */
    int count() {
        return slots.get();
    }

    long cut() {
        return cut.get();
    }

    /** Events a stream did not get because it was cut (those it had queued and the one that did not fit). */
    long dropped() {
        return dropped.get();
    }
}
