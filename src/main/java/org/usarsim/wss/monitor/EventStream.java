package org.usarsim.wss.monitor;

import com.sun.net.httpserver.HttpExchange;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.logging.Logger;

/**
 * One viewer's GET /api/events: a bounded queue the publisher offers to (never waits), written to
 * the viewer by a thread of its own. A queue that fills (the viewer does not read) cuts the stream:
 * the queue is emptied at once (its memory given back), and the thread ends the response as soon as
 * its write in progress returns (a viewer that is stopped holds it until it reads again or its
 * connection dies). Without an event for {@link #KEEPALIVE_NS} a comment line keeps the connection
 * alive and finds a vanished viewer.
 */
final class EventStream implements Runnable {

    private static final Logger LOG = Logger.getLogger(EventStream.class.getName());
    static final int MAX_QUEUED = 1024;
    static final long MAX_QUEUED_BYTES = 8L * 1024 * 1024;
    static final long KEEPALIVE_NS = TimeUnit.SECONDS.toNanos(15);
    private static final byte[] KEEPALIVE = ": keepalive\n\n".getBytes(StandardCharsets.US_ASCII);

    private final HttpExchange exchange;
    private final String who;
    private final Consumer<EventStream> ended;
    private final ArrayDeque<SseEvent> queue = new ArrayDeque<>();
    private long queuedBytes;
    /** Guarded by this: the events a cut left undelivered (those queued and the one refused). */
    private int lostAtCut;
    /** Guarded by this: no more events (cut, or the server stops). */
    private boolean closed;

    /** @param ended told once when the thread is done with the exchange (the stream's slot is free again) */
    EventStream(HttpExchange exchange, String who, Consumer<EventStream> ended) {
        this.exchange = exchange;
        this.who = who;
        this.ended = ended;
    }

    String who() {
        return who;
    }

    void start(int number) {
        Thread thread = new Thread(this, "wss-monitor-stream-" + number);
        thread.setDaemon(true);
        thread.start();
    }

    /**
     * Queues the event; false when the queue is full (and the stream is then cut: the caller counts
     * it) or the stream is closed. The first event is taken whatever its size (a snapshot).
     */
    synchronized boolean offer(SseEvent event) {
        if (closed) {
            return false;
        }
        if (!queue.isEmpty() && (queue.size() >= MAX_QUEUED || queuedBytes + event.wire().length > MAX_QUEUED_BYTES)) {
            lostAtCut = queue.size() + 1;
            close();
            return false;
        }
        queue.addLast(event);
        queuedBytes += event.wire().length;
        notifyAll();
        return true;
    }

    /** The events the cut left undelivered (0 unless cut). */
    synchronized int lostAtCut() {
        return lostAtCut;
    }

    /** No more events: the queue is dropped, the response ends once the thread can write again. */
    synchronized void close() {
        closed = true;
        queue.clear();
        queuedBytes = 0;
        notifyAll();
    }

    /** The events queued, waiting up to the keepalive for one; empty: write a keepalive; null: closed. */
    synchronized List<SseEvent> take() throws InterruptedException {
        long deadline = System.nanoTime() + KEEPALIVE_NS;
        while (queue.isEmpty() && !closed) {
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                return List.of();
            }
            TimeUnit.NANOSECONDS.timedWait(this, left);
        }
        if (closed) {
            return null;
        }
        List<SseEvent> taken = new ArrayList<>(queue);
        queue.clear();
        queuedBytes = 0;
        return taken;
    }

    @Override
    public void run() {
        try (OutputStream out = exchange.getResponseBody()) {
            List<SseEvent> events;
            while ((events = take()) != null) {
                if (events.isEmpty()) {
                    out.write(KEEPALIVE);
                }
                for (SseEvent event : events) {
                    out.write(event.wire());
                }
                out.flush();
            }
        } catch (IOException e) {
            LOG.fine(() -> "monitor: the event stream of " + who + " ended: " + e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            close();
            exchange.close();
            ended.accept(this);
        }
    }
}
