package org.usarsim.wss.world;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.DoubleSupplier;
import java.util.logging.Logger;
import org.usarsim.wss.net.LogLimiter;

/**
 * Serves USARSim's position protocol from a world file, so that the simulator-driven
 * propagation models run without USARSim: each client gets its own thread, and every answer is
 * the world at the moment the command is read, timed from when the server started listening.
 */
public final class WorldServer implements AutoCloseable {

    private static final Logger LOG = Logger.getLogger(WorldServer.class.getName());

    private final World world;
    private final DoubleSupplier clock;
    private final ClientPort<WorldClient> port;

    /**
     * Reads the world file, then listens on the address and port (0: any free port) and serves
     * until {@link #close()}. A bad file is reported before anything is bound.
     *
     * @throws WorldFileException the file cannot be read or is wrong; the message names the file and line
     * @throws IOException the address and port cannot be bound
     */
    public static WorldServer start(Path file, InetAddress address, int port) throws WorldFileException, IOException {
        World world = WorldFile.read(file);
        long started = System.nanoTime();
        WorldServer server = new WorldServer(world, new InetSocketAddress(address, port),
                () -> (System.nanoTime() - started) / 1e9);
        LOG.info("world server listening on " + address.getHostAddress() + ":" + server.port() + " with "
                + world.robotCount() + " robots and " + world.wallCount() + " walls from " + file);
        return server;
    }

    /** Binds and starts accepting; {@code clock} gives the seconds the world has run. */
    WorldServer(World world, InetSocketAddress address, DoubleSupplier clock) throws IOException {
        this(world, address, clock, WorldClient::start);
    }

    /** As above, with each client's thread started by {@code starter} (tests make it fail). */
    WorldServer(World world, InetSocketAddress address, DoubleSupplier clock, Consumer<WorldClient> starter) throws IOException {
        this.world = world;
        this.clock = clock;
        this.port = new ClientPort<>(address, "world-server", LOG, "world server", "client",
                (socket, serving) -> new WorldClient(this, socket), starter);
        port.start();
    }

    public int port() {
        return port.port();
    }

    /** The world now. */
    Snapshot now() {
        return world.at(clock.getAsDouble());
    }

    /**
     * The seconds the world has run: its time, which every position, stamp and publishing
     * instant of its rosbridge side ({@link RosbridgeServer#firstPublishAtOrAfter}) is told in.
     */
    public double time() {
        return clock.getAsDouble();
    }

    /** The robots' names, in file order (as {@link RosbridgeServer#firstPublishAtOrAfter} takes them). */
    public List<String> robotNames() {
        return world.robotNames();
    }

    /** The world at a time ({@link #time()}). */
    Snapshot at(double seconds) {
        return world.at(seconds);
    }

    World world() {
        return world;
    }

    /** The limit on the lines its clients cause (connected, left, an over-long line), as the WSS's. */
    LogLimiter lines() {
        return port.lines;
    }

    /**
     * Stops listening, at once, and closes every client connection; waits (at most a second) for
     * their threads to end, so that each client's "left" comes before "world server stopped" (and
     * not after whoever closed the server has gone on: Main.run puts its caller's logging back as
     * it returns).
     */
    @Override
    public void close() {
        port.close();
    }

    void ended(WorldClient client) {
        port.ended(client);
    }

    /** The clients being served. */
    int clientCount() {
        return port.size();
    }
}
