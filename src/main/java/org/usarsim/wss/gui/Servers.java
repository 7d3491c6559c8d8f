package org.usarsim.wss.gui;

import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.routes.RouteListener;
import org.usarsim.wss.routes.RouteTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * How the window starts a server: the same way headless mode does (the application supplies it),
 * so that the window never builds a hub, an event log or a model run of its own.
 */
public interface Servers {

    /**
     * Starts a server on that control port with a new instance of that model
     * ({@link ModelProvider#instanceForRun}) configured with {@code values}, the CSV event log when
     * {@code eventLog}, the run recorded when {@code record} (docs/replay.md: to the --config file's
     * wss.record, or else to a new file in the event log's folder), its links shaped as {@code shaping} says (the window's "Link shaping"), and
     * {@code listener} receiving its events from the first robot on. Slow (a model may connect to
     * the simulator): never on the event thread.
     *
     * @throws Exception when it does not start; the message says why in one line, and nothing is
     *                   left listening
     */
    Running start(String port, ModelProvider model, ModelSettings values, boolean eventLog, boolean record, ShapingConfig shaping,
            WssEventListener listener) throws Exception;

    /** A server that runs; its pairs forced and released as {@link PairControls} says (takes the hub's lock: never on the event thread). */
    interface Running extends PairControls {

        /** The control port it listens on (the one the OS chose when asked for 0). */
        int port();

        /** The model instance this server runs (the map asks it for positions, ranges and walls). */
        PropagationModel model();

        /** Its robots, ports and links at one instant (takes the hub's lock briefly: never on the event thread). */
        HubSnapshot snapshot();

        /**
         * The routes as last computed (docs/routes.md): a reference read, no lock, cheap on any
         * thread; {@link RouteTable#EMPTY} before the first.
         */
        default RouteTable routes() {
            return RouteTable.EMPTY;
        }

        /**
         * Told each time the routes change, on the hub's {@code wss-routes} thread (hand it to the
         * event thread); not when they stay the same.
         */
        default void addRouteListener(RouteListener listener) {
        }

        default void removeRouteListener(RouteListener listener) {
        }

        /** Stops it as SIGTERM does: every socket closed, the event log and the recording closed. */
        void stop();
    }
}
