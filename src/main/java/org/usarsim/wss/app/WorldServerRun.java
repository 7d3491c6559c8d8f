package org.usarsim.wss.app;

import java.io.IOException;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.logging.Level;
import org.usarsim.wss.world.RosbridgeServer;
import org.usarsim.wss.world.WorldFileException;
import org.usarsim.wss.world.WorldServer;

/**
 * {@code --world FILE [--port N] [--bind ADDRESS] [--rosbridge PORT]}: the world server (docs/world.md)
 * and, on a port not -1, its rosbridge: reads the file, listens, serves until SIGTERM or Ctrl-C.
 */
final class WorldServerRun {

    private WorldServerRun() {
    }

    /** Serves until stopped: {@link Main#OK}; a bad file or address, or a port that cannot be had, is a {@link RunFailure}. */
    static int run(PrintStream out, Options.World options) throws RunFailure {
        InetAddress address;
        try {
            address = InetAddress.getByName(options.bind());
        } catch (UnknownHostException e) {
            throw RunFailure.badInput("--bind " + options.bind() + " is not an address of this machine: " + e.getMessage());
        }
        LogSetup.install(out, Level.INFO);
        // Before anything listens: a SIGTERM right after the start line must still exit 0.
        try (StopSignal stop = new StopSignal()) {
            WorldServer server;
            try {
                server = WorldServer.start(options.file(), address, options.port());
            } catch (WorldFileException e) {
                throw RunFailure.badInput(e.getMessage());
            } catch (IOException e) {
                throw new RunFailure(Main.CANNOT_START, "cannot listen on " + address.getHostAddress() + ":" + options.port() + ": "
                        + e.getMessage());
            }
            RosbridgeServer rosbridge = null;
            try {
                if (options.rosbridge() >= 0) {
                    try {
                        rosbridge = RosbridgeServer.start(server, address, options.rosbridge(), options.rosRate(),
                                RosbridgeServer.DEFAULT_CONNECTION_DELAY);
                    } catch (IOException e) {
                        throw new RunFailure(Main.CANNOT_START, "cannot listen for rosbridge on " + address.getHostAddress() + ":"
                                + options.rosbridge() + ": " + e.getMessage());
                    }
                }
                stop.await();
            } finally {
                if (rosbridge != null) {
                    rosbridge.close();
                }
                server.close();
            }
        }
        return Main.OK;
    }
}
