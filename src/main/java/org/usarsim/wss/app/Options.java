package org.usarsim.wss.app;

import java.nio.file.Path;

/**
 * What the command line asks for, read and checked by {@link OptionsParser} before anything runs:
 * one record per action, holding what that action uses and nothing else; {@link Main} dispatches
 * on its type.
 */
sealed interface Options {

    /** The WSS: its window ({@code --start} presses Start at once), or headless ({@code --headless}, or no display); {@code config} null without {@code --config}. */
    record Serve(boolean headless, boolean start, Path config) implements Options {
    }

    /**
     * {@code --world FILE}: the world server, on {@code port} at {@code bind} (their defaults
     * filled in); {@code rosbridge} its rosbridge port, -1 when it serves none, and {@code rosRate}
     * its publishers' rate in Hz.
     */
    record World(Path file, int port, String bind, int rosbridge, double rosRate) implements Options {
    }

    /** {@code --export-world RUN.rec}: a recording written as a world file, to {@code out} ({@code --out}), or to standard output when it is null. */
    record ExportWorld(Path recording, Path out) implements Options {
    }

    /** {@code --print-ports [--config FILE]}: print the fixed ports of the configuration; {@code config} null without one. */
    record PrintPorts(Path config) implements Options {
    }

    /**
     * {@code --attach URL}: the window attached to a WSS's monitor endpoint (docs/monitor.md); the
     * token read from {@code tokenFile} (null: asked in a dialog), the server's certificate trusted
     * alone when {@code trustCert} is given (null: the JDK's default trust store).
     */
    record Attach(String url, Path tokenFile, Path trustCert) implements Options {
    }

    /** {@code --version}: print the version. */
    record Version() implements Options {
    }

    /** {@code --help}: print the help and every property of --config FILE. */
    record Help() implements Options {
    }
}
