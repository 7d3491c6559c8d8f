package org.usarsim.wss.gui;

import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.StateChangeListener;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.routes.RouteTable;

/**
 * The window's read model of the hub. The hub's events (any thread) only mark it stale: an event
 * costs the hub one atomic write and never waits for the window. The event thread calls
 * {@link #poll} a few times a second; when something changed, a snapshot of the hub is taken on
 * the view's own thread (it takes the hub's lock briefly, never on the event thread) and handed
 * back, and the next poll returns it. Many events between two polls make one snapshot, and a
 * snapshot is always the hub's whole truth: an event seen out of order, or before the window
 * started observing, cannot leave the tables wrong.
 *
 * <p>The map moves without the hub's events (the model polls positions on its own): at every poll
 * of the event thread the view thread also gathers the {@link MapData} from the model's query
 * methods (never the hub's lock) and the robots of the last snapshot, with the server's current
 * routes ({@link Servers.Running#routes}: the one place the window reads them, for the map and the
 * Routes tab alike), and {@link #pollMap} hands it over the same way.
 */
final class NetworkView implements StateChangeListener {

    private static final Logger LOG = Logger.getLogger(NetworkView.class.getName());
    /** How often a snapshot is taken even without an event: the link statistics' bytes and throughput move on. */
    static final long STATISTICS_NS = TimeUnit.SECONDS.toNanos(1);

    private final ExecutorService snapshots = Executors.newSingleThreadExecutor(task -> {
        Thread thread = new Thread(task, "wss-window-view");
        thread.setDaemon(true);
        return thread;
    });
    private final AtomicBoolean stale = new AtomicBoolean();
    private final AtomicBoolean taking = new AtomicBoolean();
    private final AtomicReference<HubSnapshot> ready = new AtomicReference<>();
    private final AtomicReference<MapData> readyMap = new AtomicReference<>();
    /** When the last snapshot was asked for (System.nanoTime()); event thread only. */
    private long askedNs;
    /** Guards {@link #source} against a snapshot of a server that stopped meanwhile. */
    private final Object sourceLock = new Object();
    private Servers.Running source;
    private PropagationModel model;
    /** The last snapshot of the source, whose robots the map shows (view thread). */
    private HubSnapshot last = HubSnapshot.EMPTY;
    /** The route table read last, and every ordered pair's route in it (view thread). */
    private RouteTable routes = RouteTable.EMPTY;
    private List<Route> allRoutes = List.of();
    /** Whether gathering the map failed since it last worked, and was said (view thread). */
    private boolean mapFailed;

    /** Observes this server, which runs {@code runModel}, from now on (the first poll takes a snapshot). */
    void attach(Servers.Running running, PropagationModel runModel) {
        synchronized (sourceLock) {
            source = running;
            model = runModel;
            stale.set(true);
        }
    }

    /** The server stopped: the next poll shows nothing. */
    void detach() {
        synchronized (sourceLock) {
            source = null;
            model = null;
            ready.set(HubSnapshot.EMPTY);
            readyMap.set(MapData.EMPTY);
        }
    }

    /**
     * Event thread: asks for the map, and for a snapshot when something changed; returns the
     * snapshot when there is a new one, else null.
     */
    HubSnapshot poll() {
        long now = System.nanoTime();
        if (now - askedNs >= STATISTICS_NS) {
            stale.set(true); // the link statistics count on without an event
        }
        if (!taking.get()) {
            Servers.Running from;
            PropagationModel of;
            synchronized (sourceLock) {
                from = source;
                of = model;
            }
            if (from != null) {
                boolean hub = stale.getAndSet(false);
                taking.set(true);
                if (hub) {
                    askedNs = now;
                }
                snapshots.execute(() -> take(from, of, hub));
            }
        }
        return ready.getAndSet(null);
    }

    /** Event thread: the map gathered since the last call, else null. */
    MapData pollMap() {
        return readyMap.getAndSet(null);
    }

    private void take(Servers.Running from, PropagationModel of, boolean hub) {
        try {
            if (hub || last == null) {
                last = from.snapshot();
            }
            HubSnapshot snapshot = last;
            MapData map = MapData.gather(snapshot, of, routes(from), allRoutes);
            synchronized (sourceLock) {
                if (source == from) {
                    if (hub) {
                        ready.set(snapshot);
                    }
                    readyMap.set(map);
                } else {
                    last = null;
                }
            }
            mapFailed = false;
        } catch (RuntimeException e) {
            if (!mapFailed) {
                LOG.log(Level.WARNING, "gathering the map failed (the model's query methods threw): " + e, e);
                mapFailed = true;
            }
        } finally {
            taking.set(false);
        }
    }

    /**
     * The server's current routes, each pair's found here when the table is new (its routes are
     * searched when first asked: here, not on the event thread), and who is cut off from the base.
     */
    private RouteTable routes(Servers.Running from) {
        RouteTable now = from.routes();
        if (now != routes) {
            allRoutes = now.all();
            now.cutOff();
            routes = now;
        }
        return now;
    }

    void close() {
        snapshots.shutdownNow();
    }

    @Override
    public void changed() {
        stale.set(true);
    }

}
