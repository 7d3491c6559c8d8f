package org.usarsim.wss.hub;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.ReentrantLock;
import org.usarsim.wss.hub.core.EventSink;
import org.usarsim.wss.hub.core.HubEvent;

/**
 * The hub's one event path: events are appended in the order the changes happened (by the hub,
 * under its lock, as the core returns them) and delivered in that order, never under the hub's
 * lock, one thread at a time. A thread that finds another delivering leaves its events to it, and
 * the deliverer looks again after letting go, so none is left behind: a slow listener (a blocked
 * console) never stalls the registry.
 *
 * <p>A link waits for its establishment to be delivered ({@link #deliverThrough}) before it
 * forwards, so that its data can never come before the change that let it exist (a force up, a
 * resume) nor before its own establishment.
 */
final class Outbox {

    private final EventSink sink;
    private final List<HubEvent> pending = new ArrayList<>();
    /** How many events were ever appended, and delivered. Guarded by this object. */
    private long appended;
    private long delivered;
    /** Held by the one thread that delivers. */
    private final ReentrantLock delivering = new ReentrantLock();

    Outbox(EventSink sink) {
        this.sink = sink;
    }

    /** Appends the events in order. @return the number of the last event appended so far */
    synchronized long append(List<HubEvent> events) {
        pending.addAll(events);
        appended += events.size();
        return appended;
    }

    /**
     * Delivers the pending events in order. A listener that changes the hub from its event (the
     * delivering thread itself) leaves its events to the loop it is called from, which delivers
     * them after the rest of the batch it is in: delivering them at once would put them before
     * events that came first.
     */
    void deliver() {
        if (delivering.isHeldByCurrentThread()) {
            return;
        }
        while (delivering.tryLock()) {
            try {
                List<HubEvent> batch;
                while (!(batch = take()).isEmpty()) {
                    batch.forEach(event -> event.deliverTo(sink));
                    delivered(batch.size());
                }
            } finally {
                delivering.unlock();
            }
            synchronized (this) {
                if (pending.isEmpty()) {
                    return;
                }
            }
        }
    }

    /** Delivers, and returns once every event up to number {@code last} has been delivered (by this thread or another). */
    void deliverThrough(long last) {
        while (true) {
            deliver();
            if (delivering.isHeldByCurrentThread()) {
                return; // a listener's own change: its batch comes after the one it is in
            }
            synchronized (this) {
                if (delivered >= last) {
                    return;
                }
                if (delivering.isLocked()) {
                    try {
                        wait(100); // notified at each batch delivered
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        return;
                    }
                }
            }
        }
    }

    private synchronized List<HubEvent> take() {
        List<HubEvent> batch = List.copyOf(pending);
        pending.clear();
        return batch;
    }

    private synchronized void delivered(int count) {
        delivered += count;
        notifyAll();
    }
}
