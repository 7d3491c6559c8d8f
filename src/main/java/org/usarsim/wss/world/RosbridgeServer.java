package org.usarsim.wss.world;

import org.usarsim.wss.Decimals;
import java.io.IOException;
import java.math.BigDecimal;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.List;
import java.util.logging.Logger;
import org.usarsim.wss.net.LogLimiter;

/**
 * The world server's world over rosbridge v2 ({@code --world F --rosbridge PORT}, docs/world.md):
 * a WebSocket server (RFC 6455) on a port of its own, beside the USARSim position port, serving
 * the same world at the same time as a rosbridge_suite 0.11.17 in front of a ROS graph would: the
 * graph's publishers ({@link RosGraph}) publish at their rate in the world's time, and each
 * client's subscriptions take their messages as rosbridge's do ({@link TopicSubscription}). Each
 * client gets a thread ({@link RosbridgeClient}) that reads its requests and sends what is due. At
 * most {@link #MAX_CLIENTS} clients at once (one more is answered 503 and closed), requests of at
 * most {@link #MAX_MESSAGE_BYTES} (a longer one closes the connection, 1009); the lines clients
 * cause go through a {@link LogLimiter} as the world server's do.
 */
public final class RosbridgeServer implements AutoCloseable {

    private static final Logger LOG = Logger.getLogger(RosbridgeServer.class.getName());

    /** The publishers' rate unless told otherwise ({@code --ros-rate}): 20 Hz. */
    public static final double DEFAULT_RATE_HZ = RosGraph.DEFAULT_RATE_HZ;
    /** The fastest rate of its publishers, in Hz ({@code --ros-rate}). */
    public static final double MAX_RATE_HZ = RosGraph.MAX_RATE_HZ;
    /** How long a subscriber's connection to a per-robot topic's publisher takes unless told otherwise: 300 ms. */
    public static final Duration DEFAULT_CONNECTION_DELAY = Duration.ofNanos(RosGraph.DEFAULT_CONNECTION_DELAY_NANOS);
    /** The most clients served at once. */
    static final int MAX_CLIENTS = 64;
    /** The longest message a client may send, reassembled from its fragments: rosbridge's requests are small. */
    static final int MAX_MESSAGE_BYTES = 64 * 1024;

    private final WorldServer world;
    private final RosGraph graph;
    private final ClientPort<RosbridgeClient> port;
    private volatile String map;

    /**
     * Listens on the address and port (0: any free port) and serves the world server's world,
     * published at {@link #DEFAULT_RATE_HZ}, until {@link #close()}.
     *
     * @throws IOException the address and port cannot be bound
     */
    public static RosbridgeServer start(WorldServer world, InetAddress address, int port) throws IOException {
        return start(world, address, port, DEFAULT_RATE_HZ, DEFAULT_CONNECTION_DELAY);
    }

    /**
     * As {@link #start(WorldServer, InetAddress, int)}, every publisher at {@code rateHz}, and a
     * client's first message of a per-robot topic ({@code /NAME/odom}) only {@code connectionDelay}
     * after it subscribed.
     *
     * @throws IllegalArgumentException a rate not above 0 and at most 1000 Hz, or a negative delay
     */
    public static RosbridgeServer start(WorldServer world, InetAddress address, int port, double rateHz, Duration connectionDelay)
            throws IOException {
        RosGraph graph = new RosGraph(world.robotNames(), rateHz, connectionDelay.toNanos());
        RosbridgeServer server = new RosbridgeServer(world, graph, new InetSocketAddress(address, port));
        LOG.info("rosbridge v2 on ws://" + address.getHostAddress() + ":" + server.port() + ": " + String.join(", ",
                graph.topics().subList(0, 4)) + " and /NAME/odom, at " + Decimals.plain(BigDecimal.valueOf(rateHz))
                + " Hz");
        return server;
    }

    /**
     * The first instant, in the world's time ({@link WorldServer#time()}, seconds), at or after
     * {@code worldSeconds}, at which a world of these robots published at {@code rateHz} publishes
     * the topic: on {@code /tf}, {@code robot}'s publisher (each robot has its own); on
     * {@code /gazebo/model_states} and {@code /NAME/odom} their one publisher ({@code robot} is not
     * looked at); on the latched {@code /tf_static} and {@code /map}, 0 for a time up to 0, and
     * {@link Double#POSITIVE_INFINITY} after. Times are taken to the nanosecond (rounded).
     *
     * @param robots the world's robots, in file order ({@link WorldServer#robotNames()})
     * @throws IllegalArgumentException a topic the world does not publish, a robot not in {@code robots} on {@code /tf}, or a bad rate
     */
    public static double firstPublishAtOrAfter(String topic, String robot, List<String> robots, double rateHz, double worldSeconds) {
        long at = new RosGraph(robots, rateHz, 0).firstPublishAtOrAfter(topic, robot, Math.round(worldSeconds * 1e9));
        return at == Long.MAX_VALUE ? Double.POSITIVE_INFINITY : at / 1e9;
    }

    private RosbridgeServer(WorldServer world, RosGraph graph, InetSocketAddress address) throws IOException {
        this.world = world;
        this.graph = graph;
        this.port = new ClientPort<>(address, "world-rosbridge", LOG, "rosbridge", "rosbridge client",
                (socket, serving) -> new RosbridgeClient(this, socket, serving >= MAX_CLIENTS), RosbridgeClient::start);
        port.start();
    }

    public int port() {
        return port.port();
    }

    /** The world's time in nanoseconds. */
    long now() {
        return Math.round(world.time() * 1e9);
    }

    /** A new client's session. */
    RosbridgeSession session(RosbridgeSession.Out out) {
        return new RosbridgeSession(world.world(), graph, this::map, out);
    }

    /** The limit on the lines its clients cause, as the world server's. */
    LogLimiter lines() {
        return port.lines;
    }

    /** The {@code /map} frame: the walls do not change, so it is made once, at the first it is sent, stamped 0 (latched). */
    private String map() {
        String made = map;
        if (made == null) {
            synchronized (this) {
                if (map == null) {
                    map = RosbridgeMessages.map(world.world().walls(), 0);
                }
                made = map;
            }
        }
        return made;
    }

    /** Stops listening and closes every client; waits (at most a second) for their threads to end. */
    @Override
    public void close() {
        port.close();
    }

    void ended(RosbridgeClient client) {
        port.ended(client);
    }

    int clientCount() {
        return port.size();
    }
}
