package org.usarsim.wss.hub;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.HubEvent;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.StateChangeListener;
import org.usarsim.wss.routes.BaseWatch;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.routes.RouteFinder;
import org.usarsim.wss.routes.RouteListener;
import org.usarsim.wss.routes.RouteGraph;
import org.usarsim.wss.routes.RouteTable;

/**
 * Keeps the current routes (docs/routes.md): a listener of the hub's events that marks them stale
 * when a pair, a robot, a rate or a poll changed something, and one daemon thread,
 * {@code wss-routes}, that recomputes them from a {@link HubSnapshot} (taken off the hub's lock but
 * for its copy), coalescing every change that came meanwhile; a new table, when it differs from the
 * last, is handed to the {@link RouteListener}s, and what it changed of the robots' routes to the
 * base ({@link BaseWatch}) to the hub's events.
 */
final class RouteKeeper implements StateChangeListener {

    private static final Logger LOG = Logger.getLogger(RouteKeeper.class.getName());

    /** The graph the routes are found over, now, for a base (null: none). */
    private final Function<String, RouteGraph> graphs;
    /** Where the base's lines go: the hub's events, in order with the rest. */
    private final Consumer<HubEvent> announce;
    /** Only on the routes' thread. */
    private final BaseWatch baseWatch = new BaseWatch();
    private final List<RouteListener> listeners = new CopyOnWriteArrayList<>();
    private volatile RouteTable current = RouteTable.EMPTY;
    /** Guarded by this. */
    private boolean stale;
    private boolean closed;
    private String base;
    private Thread thread;

    RouteKeeper(Function<String, RouteGraph> graphs, Consumer<HubEvent> announce) {
        this.graphs = graphs;
        this.announce = announce;
    }

    synchronized void start() {
        thread = new Thread(this::run, "wss-routes");
        thread.setDaemon(true);
        thread.start();
        stale();
    }

    synchronized void close() {
        closed = true;
        notifyAll();
    }

    /** The routes as last computed ({@link RouteTable#EMPTY} before the first). */
    RouteTable current() {
        return current;
    }

    void addListener(RouteListener listener) {
        listeners.add(listener);
    }

    void removeListener(RouteListener listener) {
        listeners.remove(listener);
    }

    /** Robots are cut off from this one from now on (null: none). */
    synchronized void base(String robot) {
        base = robot;
        stale();
    }

    synchronized String base() {
        return base;
    }

    /** Something that routes depend on changed: they are recomputed soon, once for all that came meanwhile. */
    synchronized void stale() {
        stale = true;
        notifyAll();
    }

    private void run() {
        while (true) {
            String of;
            synchronized (this) {
                while (!stale && !closed) {
                    try {
                        wait();
                    } catch (InterruptedException e) {
                        return;
                    }
                }
                if (closed) {
                    return;
                }
                stale = false;
                of = base;
            }
            try {
                recompute(of);
            } catch (RuntimeException e) {
                LOG.log(Level.WARNING, "finding the routes failed: " + e, e); // the next change tries again
            }
        }
    }

    private void recompute(String of) {
        RouteTable table = RouteFinder.table(graphs.apply(of));
        if (table.equals(current)) {
            return;
        }
        current = table;
        for (RouteListener listener : listeners) {
            try {
                listener.routesChanged(table);
            } catch (RuntimeException e) {
                LOG.log(Level.WARNING, "a route listener failed: " + e, e);
            }
        }
        for (BaseWatch.Change change : baseWatch.next(table)) {
            Route route = change.route();
            announce.accept(change.cutOff() ? new HubEvent.CutOff(change.robot())
                    : new HubEvent.RoutedToBase(change.robot(), route.hops(), route.pathText(), route.rateBound()));
        }
    }

    // ---- what makes the routes stale: every change of robots, pairs, rates (StateChangeListener), and a poll; not data ----

    @Override
    public void changed() {
        stale();
    }

    @Override
    public void cutOff(String robot) {
        // the routes' own news: nothing changed that they are found over
    }

    @Override
    public void routedToBase(String robot, int hops, String path, long bitsPerSecond) {
        // the routes' own news
    }

    @Override
    public void polled(ModelPoll poll) {
        stale(); // strengths move with the robots
    }
}
