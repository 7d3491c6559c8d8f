package org.usarsim.wss.sim;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Path;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import java.util.function.DoubleSupplier;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Serves USARSim's position protocol from a world file, so that the simulator-driven
 * propagation models run without USARSim: each client gets its own thread, and every answer is
 * the world at the moment the command is read, timed from when the server started listening.
 */
public final class WorldServer implements AutoCloseable {

    private static final Logger LOG = Logger.getLogger(WorldServer.class.getName());

    private final World world;
    private final DoubleSupplier clock;
    private final ServerSocket server;
    private final Set<WorldClient> clients = ConcurrentHashMap.newKeySet();
    /** Starts a client's thread: {@link WorldClient#start}, or what a test puts in its place. */
    private final Consumer<WorldClient> starter;
    private final Thread acceptor;
    private final AtomicBoolean closed = new AtomicBoolean();

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
        this.server = new ServerSocket();
        try {
            server.setReuseAddress(true);
            server.bind(address, 50);
        } catch (IOException e) {
            server.close();
            throw e;
        }
        this.acceptor = new Thread(this::accept, "world-server " + port());
        acceptor.setDaemon(true);
        acceptor.start();
    }

    int port() {
        return server.getLocalPort();
    }

    /** The world now. */
    Snapshot now() {
        return world.at(clock.getAsDouble());
    }

    /** Stops listening, at once, and closes every client connection. */
    @Override
    public void close() {
        // Not server.isClosed(): the acceptor closes the socket itself when it gives up (serve).
        if (!closed.compareAndSet(false, true)) {
            return;
        }
        try {
            server.close();
        } catch (IOException e) {
            LOG.fine(() -> "closing the world server's socket: " + e);
        }
        // The socket is released only when the thread blocked in accept() has let go of it.
        try {
            acceptor.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        clients.forEach(WorldClient::close);
        LOG.info("world server stopped");
    }

    void ended(WorldClient client) {
        clients.remove(client);
    }

    /** The clients being served. */
    int clientCount() {
        return clients.size();
    }

    private void accept() {
        while (!server.isClosed()) {
            Socket socket;
            try {
                socket = server.accept();
            } catch (IOException e) {
                if (server.isClosed()) {
                    return;
                }
                // Out of descriptors, say: clients must still be able to connect once it passes.
                LOG.log(Level.SEVERE, "accepting a client failed, trying again: " + e, e);
                pause();
                continue;
            }
            serve(socket);
        }
    }

    /**
     * Gives the client its thread. When that fails (an OutOfMemoryError "unable to create native
     * thread", say) only this client is dropped: its connection is closed, it is forgotten, and
     * the acceptor goes on with the next. A VirtualMachineError other than an OutOfMemoryError
     * leaves the JVM in doubt: then the server also stops listening, so that clients are refused
     * rather than left waiting on a bound port, and the error goes on up.
     */
    private void serve(Socket socket) {
        WorldClient client = null;
        try {
            client = new WorldClient(this, socket);
            clients.add(client);
            if (server.isClosed()) {
                client.close();
            }
            starter.accept(client);
        } catch (Throwable e) {
            String peer = socket.getInetAddress().getHostAddress() + ":" + socket.getPort();
            if (client != null) {
                clients.remove(client);
            }
            try {
                socket.close();
            } catch (IOException closing) {
                e.addSuppressed(closing);
            }
            if (e instanceof VirtualMachineError && !(e instanceof OutOfMemoryError)) {
                LOG.log(Level.SEVERE, "cannot serve client " + peer + " (" + e + "): the world server stops listening", e);
                try {
                    server.close();
                } catch (IOException closing) {
                    e.addSuppressed(closing);
                }
                throw (VirtualMachineError) e;
            }
            LOG.log(Level.WARNING, "cannot serve client " + peer + " (" + e + "): dropped it; accepting the next", e);
        }
    }

    private static void pause() {
        try {
            Thread.sleep(100);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
