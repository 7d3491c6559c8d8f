package org.usarsim.wss.app;

import java.nio.file.Path;
import org.usarsim.wss.world.RosbridgeServer;

/**
 * What the command line asks for, read and checked by {@link OptionsParser} before anything
 * runs; {@link Main} only dispatches on {@link #action}. What an action does not use is null
 * (or false): {@code port} and {@code bind} are the world server's, with their defaults filled
 * in; {@code export} and {@code out} are --export-world's; {@code rosbridge} is the world
 * server's rosbridge port, -1 when it serves none, and {@code rosRate} its publishers' rate in Hz.
 */
record Options(Action action, boolean headless, boolean start, Path config, Path world, int port, String bind,
        Path export, Path out, int rosbridge, double rosRate) {

    /** Options with the rosbridge publishers' default rate. */
    Options(Action action, boolean headless, boolean start, Path config, Path world, int port, String bind, Path export, Path out,
            int rosbridge) {
        this(action, headless, start, config, world, port, bind, export, out, rosbridge, RosbridgeServer.DEFAULT_RATE_HZ);
    }

    /** What Main does. */
    enum Action {
        /** The WSS: its window, or headless ({@code --headless}, or no display). */
        SERVE,
        /** {@code --world FILE}: the world server. */
        WORLD,
        /** {@code --export-world RUN.rec}: a recording written as a world file. */
        EXPORT_WORLD,
        /** {@code --print-ports [--config FILE]}: print the fixed ports of the configuration. */
        PRINT_PORTS,
        /** {@code --version}: print the version. */
        VERSION,
        /** {@code --help}: print the help and every property of --config FILE. */
        HELP
    }
}
