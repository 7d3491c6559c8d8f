package org.usarsim.wss.app;

/**
 * The defaults a user meets on the command line and in a properties file that are the
 * application's own, named once (--help prints them). The control port's is the protocol's
 * ({@code protocol.ControlPort.DEFAULT}), the model's the catalog's
 * ({@code model.ModelCatalog.DEFAULT_MODEL}): the window reads those too.
 */
final class Defaults {

    /** The world server's port (--port): USARSim's position port. */
    static final int WORLD_PORT = 7435;

    /** The address that listens on every interface (wss.bindAddress, --bind). */
    static final String ALL_INTERFACES = "0.0.0.0";

    /** Seconds between two statistics tables in the headless log (wss.statsInterval): 0, never. */
    static final int STATS_INTERVAL = 0;

    private Defaults() {
    }
}
