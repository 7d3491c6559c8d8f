package org.usarsim.wss.routes;

/** Told each time the routes change (not at each poll: only when the table differs from the last one). */
@FunctionalInterface
public interface RouteListener {

    /**
     * The routes now. Called on the hub's {@code wss-routes} thread, never under its lock: a
     * window hands it to its event thread; a listener that throws is logged.
     */
    void routesChanged(RouteTable routes);
}
