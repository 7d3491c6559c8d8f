package org.usarsim.wss.gui;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.model.WssEventListener;

/**
 * The window's read model of the hub. The hub's events (any thread) only mark it stale: an event
 * costs the hub one atomic write and never waits for the window. The event thread calls
 * {@link #poll} a few times a second; when something changed, a snapshot of the hub is taken on
 * the view's own thread (it takes the hub's lock briefly, never on the event thread) and handed
 * back, and the next poll returns it. Many events between two polls make one snapshot, and a
 * snapshot is always the hub's whole truth: an event seen out of order, or before the window
 * started observing, cannot leave the tables wrong.
 */
final class NetworkView implements WssEventListener {

    /** How often a snapshot is taken even without an event: the link statistics' bytes and throughput move on. */
    static final long STATISTICS_NS = java.util.concurrent.TimeUnit.SECONDS.toNanos(1);

    private final ExecutorService snapshots = Executors.newSingleThreadExecutor(task -> {
        Thread thread = new Thread(task, "wss-window-view");
        thread.setDaemon(true);
        return thread;
    });
    private final AtomicBoolean stale = new AtomicBoolean();
    private final AtomicBoolean taking = new AtomicBoolean();
    private final AtomicReference<HubSnapshot> ready = new AtomicReference<>();
    /** When the last snapshot was asked for (System.nanoTime()); event thread only. */
    private long askedNs;
    /** Guards {@link #source} against a snapshot of a server that stopped meanwhile. */
    private final Object sourceLock = new Object();
    private Servers.Running source;

    /** Observes this server from now on (the first poll takes a snapshot). */
    void attach(Servers.Running running) {
        synchronized (sourceLock) {
            source = running;
            stale.set(true);
        }
    }

    /** The server stopped: the next poll shows nothing. */
    void detach() {
        synchronized (sourceLock) {
            source = null;
            ready.set(HubSnapshot.EMPTY);
        }
    }

    /** Event thread: asks for a snapshot when something changed; returns one when there is a new one, else null. */
    HubSnapshot poll() {
        long now = System.nanoTime();
        if (now - askedNs >= STATISTICS_NS) {
            stale.set(true); // the link statistics count on without an event
        }
        if (!taking.get() && stale.get()) {
            Servers.Running from;
            synchronized (sourceLock) {
                from = source;
            }
            if (from != null && stale.getAndSet(false)) {
                taking.set(true);
                askedNs = now;
                snapshots.execute(() -> take(from));
            }
        }
        return ready.getAndSet(null);
    }

    private void take(Servers.Running from) {
        try {
            HubSnapshot snapshot = from.snapshot();
            synchronized (sourceLock) {
                if (source == from) {
                    ready.set(snapshot);
                }
            }
        } finally {
            taking.set(false);
        }
    }

    void close() {
        snapshots.shutdownNow();
    }

    private void changed() {
        stale.set(true);
    }

    @Override
    public void robotRegistered(String robot, String address, java.util.List<Integer> ports) {
        changed();
    }

    @Override
    public void robotDeregistered(String robot) {
        changed();
    }

    @Override
    public void connectionEstablished(String from, String to, int targetPort) {
        changed();
    }

    @Override
    public void connectionTerminated(String from, String to, int targetPort) {
        changed();
    }

    @Override
    public void portAllocated(String from, String to, int targetPort, int wssPort, boolean listening) {
        changed();
    }

    @Override
    public void portListening(String from, String to, int targetPort, int wssPort, boolean listening) {
        changed();
    }

    @Override
    public void portForgotten(String from, String to, int targetPort, int wssPort) {
        changed();
    }
}
