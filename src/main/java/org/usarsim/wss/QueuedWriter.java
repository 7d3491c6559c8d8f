package org.usarsim.wss;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.logging.Logger;

/**
 * A file written by one thread of its own from a bounded queue: the one rule of the CSV event log
 * and the recording (docs/architecture.md, Threads). The threads that fire events only offer an
 * item and go on: they never take a lock or wait for the disk, and wake the writer only when it
 * sleeps for want of items (not while it gathers them); when the queue is full the item is counted
 * as dropped. A link offers one per chunk it forwards, so an offer is one count, one node added to
 * a lock-free queue and one read of whether the writer sleeps (docs/performance.md, "The CSV event
 * log"). The writer takes what is queued, in order, formats it and writes it, flushing whenever
 * it has caught up (so the file is current while it is open); once caught up it lets the next
 * items gather for 20 ms, so that a busy source costs it one wake-up and one write per batch
 * rather than per item. After a batch in which items were dropped, the format writes how many. {@link #close} queues the end and waits (at most 10 s, for a disk that
 * hangs) until everything before it is written and the file closed. A disk that fails is said
 * once; then nothing more is written.
 *
 * @param <T> what is queued
 */
public final class QueuedWriter<T> implements AutoCloseable {

    /** How the items become text. Called on the writer's thread only. */
    public interface Format<T> {

        void append(StringBuilder text, T item);

        /** After a batch: {@code count} items were dropped since the last time this was called. */
        void dropped(StringBuilder text, long count);

        /** The end, once, at {@link #close}: the last text of the file (none by default). */
        default void end(StringBuilder text) {
        }
    }

    private static final int BATCH = 1024;
    private static final long GATHER_MS = 20;
    private static final long CLOSE_WAIT_SECONDS = 10;
    /** Queued by {@link #close}: the writer stops after it. */
    private static final Object END = new Object();

    private final Logger log;
    private final String what;
    private final Writer out;
    private final Format<T> format;
    /** The items in the order they were offered, and {@link #END}; at most {@code capacity} items. */
    private final Queue<Object> queue = new ConcurrentLinkedQueue<>();
    private final int capacity;
    /** How many items are in {@link #queue}: taken by an offer, given back by the writer. */
    private final AtomicInteger queued = new AtomicInteger();
    private final AtomicLong dropped = new AtomicLong();
    /** The writer found the queue empty and sleeps (or is about to) until an offer wakes it. */
    private volatile boolean sleeping;
    private final Thread writer;
    private volatile boolean closed;
    /** Set by the writer when the file cannot be written; items are then ignored. */
    private volatile boolean failed;

    /**
     * Starts the writer thread {@code threadName} writing to {@code out} behind a queue of
     * {@code capacity} items; {@code what} names the file in the lines it writes to {@code log} (the
     * owner's: "the event log log-...txt cannot be written any more: ...").
     */
    public QueuedWriter(String threadName, Logger log, String what, Writer out, int capacity, Format<T> format) {
        this.log = log;
        this.what = what;
        this.out = out;
        this.format = format;
        this.capacity = capacity;
        this.writer = new Thread(this::writeUntilClosed, threadName);
        writer.setDaemon(true);
        writer.start();
    }

    /**
     * Any thread: queues the item, or counts it as dropped when the writer is too far behind. Never
     * waits. True when it was queued.
     */
    public boolean offer(T item) {
        if (closed || failed) {
            return false;
        }
        if (queued.getAndIncrement() >= capacity) {
            queued.decrementAndGet();
            dropped.incrementAndGet();
            return false;
        }
        queue.offer(item);
        wake();
        return true;
    }

    /** After an item is queued: wakes the writer if it sleeps for want of one. */
    private void wake() {
        if (sleeping) {
            LockSupport.unpark(writer);
        }
    }

    /**
     * The writer: the next item, sleeping until there is one. It says it sleeps before it looks
     * a last time, and an offer queues before it looks whether the writer sleeps, so one of the
     * two sees the other: no item is left waiting while the writer sleeps.
     */
    private Object next() throws InterruptedException {
        Object item = queue.poll();
        while (item == null) {
            sleeping = true;
            item = queue.poll();
            if (item == null) {
                LockSupport.park(this);
                if (Thread.interrupted()) {
                    throw new InterruptedException();
                }
                item = queue.poll();
            }
            sleeping = false;
        }
        return item;
    }

    /** The writer: up to {@code max} more items that are queued now, in order. */
    private void drainTo(List<Object> batch, int max) {
        for (int i = 0; i < max; i++) {
            Object item = queue.poll();
            if (item == null) {
                return;
            }
            batch.add(item);
        }
    }

    /** Counts an item its source would not queue (the recording's cap on queued polls). */
    public void drop() {
        dropped.incrementAndGet();
    }

    /** Whether items are still taken: not closed, and the file still writable. */
    public boolean open() {
        return !closed && !failed;
    }

    /** The writer thread: writes batches in order until the end, then closes the file. */
    @SuppressWarnings("unchecked")
    private void writeUntilClosed() {
        List<Object> batch = new ArrayList<>(BATCH);
        StringBuilder text = new StringBuilder(64 * BATCH);
        boolean end = false;
        boolean caughtUp = true;
        try {
            while (!end) {
                batch.add(next());
                if (caughtUp && batch.get(0) != END) {
                    Thread.sleep(GATHER_MS);
                }
                drainTo(batch, BATCH - 1);
                int items = 0;
                for (Object item : batch) {
                    if (item == END) {
                        end = true;
                        break;
                    }
                    format.append(text, (T) item);
                    items++;
                }
                queued.addAndGet(-items);
                batch.clear();
                long lost = dropped.getAndSet(0);
                if (lost > 0) {
                    format.dropped(text, lost);
                }
                if (end) {
                    format.end(text);
                }
                caughtUp = queue.isEmpty();
                write(text, end || caughtUp);
                text.setLength(0);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            try {
                out.close();
            } catch (IOException e) {
                if (!failed) {
                    log.warning("closing " + what + ": " + e.getMessage());
                }
            }
        }
    }

    private void write(StringBuilder text, boolean flush) {
        if (failed) {
            return;
        }
        try {
            out.append(text);
            if (flush) {
                out.flush();
            }
        } catch (IOException e) {
            failed = true;
            log.warning(what + " cannot be written any more: " + e.getMessage());
        }
    }

    /**
     * Stops taking items, waits (at most 10 s, for a disk that hangs) until the writer has written
     * everything queued before, the count of any dropped and the end, and closed the file.
     */
    @Override
    public void close() {
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
        }
        queue.offer(END); // beyond the capacity, which bounds the items alone
        wake();
        try {
            writer.join(TimeUnit.SECONDS.toMillis(CLOSE_WAIT_SECONDS));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (writer.isAlive()) {
            log.warning(what + " was still being written " + CLOSE_WAIT_SECONDS + " s after the server stopped");
        }
    }
}
