package org.usarsim.wss.world;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import java.util.function.DoubleSupplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.net.AcceptLoop;
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
    private final ServerSocketChannel server;
    private final ServedClients<WorldClient> clients = new ServedClients<>();
    /** Starts a client's thread: {@link WorldClient#start}, or what a test puts in its place. */
    private final Consumer<WorldClient> starter;
    private final Thread acceptor;
    private final AtomicBoolean closed = new AtomicBoolean();
    /** The limit on the lines its clients cause (connected, left, an over-long line), as the WSS's. */
    final LogLimiter lines = LogLimiter.standard("world-warnings");

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
        this.starter = starter;
        this.server = AcceptLoop.bind(address, AcceptLoop.BACKLOG);
        this.acceptor = new Thread(new Acceptor(server), "world-server " + port());
        acceptor.setDaemon(true);
        acceptor.start();
    }

    public int port() {
        return server.socket().getLocalPort();
    }

    /** The world now. */
    Snapshot now() {
        return world.at(clock.getAsDouble());
    }

    /** The seconds the world has run. */
    double time() {
        return clock.getAsDouble();
    }

    /** The world at a time ({@link #time()}). */
    Snapshot at(double seconds) {
        return world.at(seconds);
    }

    /** Stops listening, at once, and closes every client connection; waits (at most a second) for their threads to end. */
    @Override
    public void close() {
        // Not server.isOpen(): the acceptor closes the socket itself when it gives up (AcceptLoop).
        if (!closed.compareAndSet(false, true)) {
            return;
        }
        // Their threads say "left" before "stopped", not after whoever closed the server has gone on
        // (Main.run puts its caller's logging back as it returns).
        clients.closeAll(server, acceptor);
        lines.close();
        LOG.info("world server stopped");
    }

    void ended(WorldClient client) {
        clients.ended(client);
    }

    /** The clients being served. */
    int clientCount() {
        return clients.size();
    }

    /** The acceptor: gives each client its thread, with {@link AcceptLoop}'s policy when that fails. */
    private final class Acceptor extends AcceptLoop {

        Acceptor(ServerSocketChannel server) {
            super(server, LOG, "the world server", "client");
        }

        @Override
        protected void serve(SocketChannel socket) {
            clients.serve(new WorldClient(WorldServer.this, socket.socket()), server, starter);
        }

        @Override
        protected boolean acceptFailed(IOException e) {
            // Out of descriptors, say: clients must still be able to connect once it passes.
            LOG.log(Level.SEVERE, "accepting a client failed, trying again: " + e, e);
            return false;
        }
    }
}
