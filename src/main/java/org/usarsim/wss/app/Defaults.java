package org.usarsim.wss.app;

/** The defaults a user meets on the command line and in a properties file, named once (--help prints them). */
final class Defaults {

    /** The WSS's control port, robots connect to (wss.port). */
    static final int CONTROL_PORT = 50000;

    /** The world server's port (--port): USARSim's position port. */
    static final int WORLD_PORT = 7435;

    /** The address that listens on every interface (wss.bindAddress, --bind). */
    static final String ALL_INTERFACES = "0.0.0.0";

    /** Seconds between two statistics tables in the headless log (wss.statsInterval): 0, never. */
    static final int STATS_INTERVAL = 0;

    private Defaults() {
    }
}
