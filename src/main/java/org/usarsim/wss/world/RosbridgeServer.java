package org.usarsim.wss.world;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.net.AcceptLoop;
import org.usarsim.wss.net.LogLimiter;

/**
 * The world server's world over rosbridge v2 ({@code --world F --rosbridge PORT},
 * docs/world.md): a WebSocket server (RFC 6455) on a port of its own, beside the USARSim
 * position port, serving the same world at the same time. Each client gets a thread
 * ({@link RosbridgeClient}) that reads its requests and publishes its subscriptions at the tick,
 * every {@link #TICK_NANOS}. At most {@link #MAX_CLIENTS} clients at once (one more is answered
 * 503 and closed), requests of at most {@link #MAX_MESSAGE_BYTES} (a longer one closes the
 * connection, 1009); the lines clients cause go through a {@link LogLimiter} as the world
 * server's do.
 */
public final class RosbridgeServer implements AutoCloseable {

    private static final Logger LOG = Logger.getLogger(RosbridgeServer.class.getName());

    /** The tick: 50 a second, so that a client's throttle_rate of 200 ms (5 Hz) or 50 ms (20 Hz) is kept to the tick. */
    static final long TICK_NANOS = 20_000_000L;
    /** The most clients served at once. */
    static final int MAX_CLIENTS = 64;
    /** The longest message a client may send, reassembled from its fragments: rosbridge's requests are small. */
    static final int MAX_MESSAGE_BYTES = 64 * 1024;

    private final WorldServer world;
    private final ServerSocketChannel server;
    private final ServedClients<RosbridgeClient> clients = new ServedClients<>();
    private final Thread acceptor;
    private final AtomicBoolean closed = new AtomicBoolean();
    private volatile String map;
    /** The limit on the lines its clients cause, as the world server's. */
    final LogLimiter lines = LogLimiter.standard("rosbridge-warnings");

    /**
     * Listens on the address and port (0: any free port) and serves the world server's world
     * until {@link #close()}.
     *
     * @throws IOException the address and port cannot be bound
     */
    public static RosbridgeServer start(WorldServer world, InetAddress address, int port) throws IOException {
        RosbridgeServer server = new RosbridgeServer(world, new InetSocketAddress(address, port));
        LOG.info("rosbridge v2 on ws://" + address.getHostAddress() + ":" + server.port() + ": " + RosbridgeMessages.MODEL_STATES
                + ", " + RosbridgeMessages.TF + ", " + RosbridgeMessages.MAP + " and /NAME/odom");
        return server;
    }

    private RosbridgeServer(WorldServer world, InetSocketAddress address) throws IOException {
        this.world = world;
        this.server = AcceptLoop.bind(address, AcceptLoop.BACKLOG);
        this.acceptor = new Thread(new Acceptor(server), "world-rosbridge " + port());
        acceptor.setDaemon(true);
        acceptor.start();
    }

    public int port() {
        return server.socket().getLocalPort();
    }

    WorldServer world() {
        return world;
    }

    /** The {@code /map} frame: the walls do not change, so it is made once, at the first subscribe. */
    String map() {
        String made = map;
        if (made == null) {
            synchronized (this) {
                if (map == null) {
                    map = RosbridgeMessages.map(world.now().walls(), world.time());
                }
                made = map;
            }
        }
        return made;
    }

    /** Stops listening and closes every client; waits (at most a second) for their threads to end. */
    @Override
    public void close() {
        if (!closed.compareAndSet(false, true)) {
            return;
        }
        clients.closeAll(server, acceptor);
        lines.close();
        LOG.info("rosbridge stopped");
    }

    void ended(RosbridgeClient client) {
        clients.ended(client);
    }

    int clientCount() {
        return clients.size();
    }

    private final class Acceptor extends AcceptLoop {

        Acceptor(ServerSocketChannel server) {
            super(server, LOG, "the rosbridge server", "rosbridge client");
        }

        @Override
        protected void serve(SocketChannel socket) {
            boolean busy = clients.size() >= MAX_CLIENTS;
            clients.serve(new RosbridgeClient(RosbridgeServer.this, socket.socket(), busy), server, RosbridgeClient::start);
        }

        @Override
        protected boolean acceptFailed(IOException e) {
            LOG.log(Level.SEVERE, "accepting a rosbridge client failed, trying again: " + e, e);
            return false;
        }
    }
}
