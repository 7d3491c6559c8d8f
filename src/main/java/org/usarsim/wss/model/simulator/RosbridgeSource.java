package org.usarsim.wss.model.simulator;

import java.io.IOException;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.time.Duration;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.net.LogLimiter;
import org.usarsim.wss.ros.Json;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.JsonNode;
import org.usarsim.wss.ros.MessageType;
import org.usarsim.wss.ros.OccupancyGrid;
import org.usarsim.wss.ros.PoseDecoder;
import org.usarsim.wss.ros.RobotPose;
import org.usarsim.wss.ros.RosFrame;

/**
 * Positions from a rosbridge v2 server (docs/ros.md): one WebSocket (the JDK's client), one
 * subscription to the poses' topic (or one per robot, for {@code /{robot}/odom}) with
 * {@code throttle_rate} the poll interval and {@code queue_length} 1. The poses arrive on the
 * WebSocket's thread, whole messages reassembled from their fragments up to the size limit, are
 * decoded by {@link PoseDecoder} and kept, the latest per robot with its stamp and arrival time;
 * each poll takes what is fresh.
 *
 * <p>Two cases kept apart: the source is <em>silent</em> ({@link #positions} throws: the WebSocket
 * closed, or nothing at all came for the stale limit), and the model keeps its last state and opens
 * another; a robot is <em>unlisted</em> (absent from the latest {@code ModelStates}, or its pose
 * older than the stale limit: by its stamp against the newest stamp, where it has one, since ROS
 * time may be simulation time; by its arrival where not), and the model kicks it. A frame that
 * cannot be read is one line in the log, limited as warnings are, and changes nothing.
 */
final class RosbridgeSource implements PositionSource {

    private static final Logger LOG = Logger.getLogger(RosbridgeSource.class.getName());
    /** How long opening the WebSocket may take. */
    static final Duration CONNECT_TIMEOUT = Duration.ofSeconds(5);

    /** What a run says once, whichever of its connections learns it first. */
    static final class RunNotes {
        private boolean saidPositions;
        private boolean saidGrid;
        private final Set<String> saidQuiet = new HashSet<>();
    }

    /** One kept pose: where, its stamp ({@link RobotPose#NO_STAMP} for none), when it arrived. */
    private record Entry(ReportedRobot robot, long stamp, long arrival) {
    }

    private final RosbridgeConfig config;
    private final PollClock clock;
    private final RunNotes notes;
    private final LogLimiter limiter;
    private final PoseDecoder decoder;
    private final long staleNs;

    // Shared between the WebSocket's thread and the poller: under this object's lock.
    private final Map<String, Entry> latest = new HashMap<>();
    private long newestStamp = Long.MIN_VALUE;
    /** When the last message came (any message), or the source opened. */
    private long lastMessage;
    /** Why the WebSocket is closed; null while it is open. */
    private String closed;
    /** Each topic subscribed, with when; removed once a message came on it. */
    private final Map<String, Long> waitingTopics = new LinkedHashMap<>();
    private final Set<String> subscribed = new LinkedHashSet<>();
    /** Whether any message came on this WebSocket. */
    private boolean messageCame;
    /** Whether a message with poses came on this WebSocket: until then it lists nothing, not "nobody". */
    private boolean posesCame;
    /** The last grid on the map topic, its walls for the map; null before one came. */
    private OccupancyGrid grid;
    private List<Wall> gridWalls;
    /** What the last poll listed, where the obstacles between are counted (the poller's only). */
    private Map<String, ReportedRobot> lastListed = Map.of();

    /** The message being reassembled from fragments (used by the WebSocket's thread only). */
    private final StringBuilder message = new StringBuilder();
    private boolean dropping;
    private WebSocket socket;
    private CompletableFuture<WebSocket> sending = CompletableFuture.completedFuture(null);

    RosbridgeSource(RosbridgeConfig config, PollClock clock, RunNotes notes, LogLimiter limiter) {
        this.config = config;
        this.clock = clock;
        this.notes = notes;
        this.limiter = limiter;
        this.decoder = new PoseDecoder(config.type(), config.frame(),
                config.perRobot() ? config.topic() : PoseDecoder.DEFAULT_ROBOT_TOPIC,
                JsonLimits.DEFAULT.withMaxChars(config.maxChars()));
        this.staleNs = TimeUnit.MILLISECONDS.toNanos(config.staleMs());
        this.lastMessage = clock.nanoTime();
    }

    /** How a run opens it: a new WebSocket each time, a run's notes and log limit kept across them; silent while unreachable. */
    static PositionSource.Opener opener(RosbridgeConfig config, PollClock clock) {
        HttpClient client = HttpClient.newBuilder().connectTimeout(CONNECT_TIMEOUT).build();
        RunNotes notes = new RunNotes();
        LogLimiter limiter = LogLimiter.standard("rosbridge-warnings");
        return new PositionSource.Opener() {
            @Override
            public PositionSource open() throws IOException {
                RosbridgeSource source = new RosbridgeSource(config, clock, notes, limiter);
                WebSocket socket;
                try {
                    socket = client.newWebSocketBuilder().connectTimeout(CONNECT_TIMEOUT)
                            .buildAsync(config.url(), source.listener()).get(CONNECT_TIMEOUT.toMillis() + 1000, TimeUnit.MILLISECONDS);
                } catch (ExecutionException e) {
                    Throwable cause = e.getCause() == null ? e : e.getCause();
                    throw new IOException("cannot open " + config.url() + ": "
                            + (cause.getMessage() == null ? cause.toString() : cause.getMessage()), cause);
                } catch (TimeoutException e) {
                    throw new IOException("cannot open " + config.url() + " within " + CONNECT_TIMEOUT.toSeconds() + " s");
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new IOException("interrupted while opening " + config.url());
                }
                source.attach(socket);
                return source;
            }

            @Override
            public String where() {
                return config.where();
            }

            @Override
            public boolean startsSilent() {
                return true;
            }
        };
    }

    /** Takes the open WebSocket and subscribes: to the poses' topic (a per-robot one at each poll), to the grid's. */
    void attach(WebSocket webSocket) {
        synchronized (this) {
            socket = webSocket;
        }
        if (!config.perRobot()) {
            subscribe(config.topic(), config.type().rosName(), config.intervalMs());
        }
        if (config.mapTopic() != null) {
            subscribe(config.mapTopic(), OccupancyGrid.TYPE, Math.max(config.intervalMs(), 1000));
        }
    }

    private void subscribe(String topic, String type, int throttleMs) {
        Map<String, Object> request = new LinkedHashMap<>();
        request.put("op", "subscribe");
        request.put("id", "wss:" + topic);
        request.put("topic", topic);
        request.put("type", type);
        request.put("throttle_rate", throttleMs);
        request.put("queue_length", 1);
        String text = Json.write(request);
        synchronized (this) {
            if (!subscribed.add(topic)) {
                return;
            }
            waitingTopics.put(topic, clock.nanoTime());
            WebSocket open = socket;
            if (open != null) {
                // One send at a time: the next goes once the last is done, or failed (the WebSocket's close says why).
                sending = sending.handle((done, failed) -> done).thenCompose(done -> open.sendText(text, true));
            }
        }
    }

    @Override
    public Map<String, ReportedRobot> positions(List<String> registered) throws IOException {
        if (config.perRobot()) {
            Set<String> robots = new LinkedHashSet<>(config.names().listed().keySet());
            robots.addAll(registered);
            robots.forEach(robot -> subscribe(config.topicOf(robot), config.type().rosName(), config.intervalMs()));
        }
        Map<String, ReportedRobot> fresh = new LinkedHashMap<>();
        Map<String, ReportedRobot> listed;
        List<String> quiet = new java.util.ArrayList<>();
        long now = clock.nanoTime();
        synchronized (this) {
            if (closed != null) {
                throw new IOException(closed);
            }
            waitingTopics.forEach((topic, since) -> {
                if (now - since >= TimeUnit.MILLISECONDS.toNanos(RosbridgeConfig.QUIET_MS) && notes.saidQuiet.add(topic)) {
                    quiet.add(topic);
                }
            });
            // A new WebSocket has at least QUIET_MS for its first message: rosbridge and the client may still be warming up.
            long limit = messageCame ? staleNs : Math.max(staleNs, TimeUnit.MILLISECONDS.toNanos(RosbridgeConfig.QUIET_MS));
            if (!subscribed.isEmpty() && now - lastMessage > limit) {
                throw new IOException("nothing from rosbridge at " + config.url() + " for "
                        + TimeUnit.NANOSECONDS.toMillis(now - lastMessage) + " ms");
            }
            if (!posesCame) {
                listed = null;
            } else {
                latest.values().stream().filter(entry -> fresh(entry, now)).sorted(java.util.Comparator.comparing(e -> e.robot().name()))
                        .forEach(entry -> fresh.put(entry.robot().name(), entry.robot()));
                listed = fresh;
            }
        }
        for (String topic : quiet) {
            LOG.warning("rosbridge at " + config.url() + " sent nothing on " + topic + " ("
                    + (topic.equals(config.mapTopic()) ? OccupancyGrid.TYPE : config.type().rosName()) + ") for "
                    + RosbridgeConfig.QUIET_MS / 1000 + " s since it was subscribed: is the topic or its type wrong?"
                    + " (rosbridge answers no error for either)");
        }
        if (listed == null) {
            return null;
        }
        boolean first;
        synchronized (notes) {
            first = !listed.isEmpty() && !notes.saidPositions;
            notes.saidPositions |= first;
        }
        if (first) {
            LOG.info("positions from " + config.where() + ": " + listed.size() + " robots");
        }
        lastListed = listed;
        return listed;
    }

    /** Whether a kept pose still lists its robot: by its stamp against the newest, or by its arrival where it has none. */
    private boolean fresh(Entry entry, long now) {
        return entry.stamp() != RobotPose.NO_STAMP ? newestStamp - entry.stamp() <= staleNs : now - entry.arrival() <= staleNs;
    }

    /** One whole message from rosbridge: poses kept, anything else said or passed over; a bad one is a line in the log. */
    void received(String text) {
        long now = clock.nanoTime();
        synchronized (this) {
            lastMessage = now;
            messageCame = true;
        }
        RosFrame frame;
        List<RobotPose> poses;
        try {
            frame = RosFrame.parse(text, JsonLimits.DEFAULT.withMaxChars(config.maxChars()));
            if (!frame.isPublish()) {
                said(frame);
                return;
            }
            synchronized (this) {
                waitingTopics.remove(frame.topic());
            }
            if (frame.topic() != null && frame.topic().equals(config.mapTopic())) {
                took(OccupancyGrid.of(frame.msg()));
                return;
            }
            poses = decoder.decode(frame);
        } catch (JsonException | RuntimeException e) {
            bad("a message that cannot be read (" + e.getMessage() + ")");
            return;
        }
        synchronized (this) {
            posesCame = true;
            if (config.type() == MessageType.MODEL_STATES) {
                latest.clear(); // each message lists every model: one it no longer lists is gone
            }
            for (RobotPose pose : poses) {
                String robot = config.names().wss(pose.name());
                if (robot == null) {
                    continue;
                }
                latest.put(robot, new Entry(new ReportedRobot(robot, pose.x(), pose.y(), pose.z(), false), pose.stampNanos(), now));
                if (pose.hasStamp()) {
                    newestStamp = Math.max(newestStamp, pose.stampNanos());
                }
            }
        }
    }

    /** A grid from the map topic: counted on from now; its walls for the map, the same list while they are the same. */
    private void took(OccupancyGrid taken) {
        List<Wall> walls = GridWalls.of(taken);
        boolean firstGrid;
        synchronized (notes) {
            firstGrid = !notes.saidGrid;
            notes.saidGrid = true;
        }
        synchronized (this) {
            grid = taken;
            if (!walls.equals(gridWalls)) {
                gridWalls = walls;
            }
        }
        if (firstGrid) {
            LOG.info("rosbridge at " + config.url() + ": an occupancy grid on " + config.mapTopic() + ", " + taken.width() + " x "
                    + taken.height() + " cells of " + taken.resolution() + " m: the obstacles between robots are counted on it");
        }
    }

    /** A frame that is not a publish: a status line is said (limited), the rest passed over. */
    private void said(RosFrame frame) {
        if ("status".equals(frame.op())) {
            String text;
            try {
                JsonNode msg = frame.root().optional("msg");
                text = msg == null ? Json.write(frame.root().value()) : msg.string();
            } catch (JsonException e) {
                text = Json.write(frame.root().value());
            }
            limiter.log(LOG, Level.WARNING, "rosbridge status", null, "rosbridge at " + config.url() + " says: " + text, null);
        }
    }

    private void bad(String what) {
        limiter.log(LOG, Level.WARNING, "bad rosbridge messages", null,
                "rosbridge at " + config.url() + " sent " + what + ": keeping the last good positions", null);
    }

    /** The grid's walls once one came on the map topic (null until then); none without a map topic. */
    @Override
    public synchronized List<Wall> walls() {
        return config.mapTopic() == null ? List.of() : gridWalls;
    }

    @Override
    public String wallsProblem() {
        return null;
    }

    /** The walls of the grid between each pair where the last poll listed them; none before a grid came. */
    @Override
    public Map<RobotPair, Double> obstacles(Collection<RobotPair> pairs) {
        OccupancyGrid counted;
        synchronized (this) {
            counted = grid;
        }
        Map<RobotPair, Double> counts = new HashMap<>();
        if (counted == null) {
            return counts;
        }
        for (RobotPair pair : pairs) {
            ReportedRobot a = lastListed.get(pair.first());
            ReportedRobot b = lastListed.get(pair.second());
            if (a != null && b != null) {
                counts.put(pair, (double) counted.crossings(a.x(), a.y(), b.x(), b.y()));
            }
        }
        return counts;
    }

    @Override
    public void close() {
        WebSocket open;
        synchronized (this) {
            open = socket;
            socket = null;
            if (closed == null) {
                closed = "closed";
            }
        }
        if (open != null) {
            open.abort();
        }
    }

    // ---- the WebSocket's side ----

    /** What the WebSocket calls, on its own thread, one call at a time. */
    WebSocket.Listener listener() {
        return new WebSocket.Listener() {
            @Override
            public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
                fragment(data, last);
                webSocket.request(1);
                return null;
            }

            @Override
            public CompletionStage<?> onBinary(WebSocket webSocket, java.nio.ByteBuffer data, boolean last) {
                if (last) {
                    bad("a binary message (not asked for)");
                }
                webSocket.request(1);
                return null;
            }

            @Override
            public CompletionStage<?> onClose(WebSocket webSocket, int statusCode, String reason) {
                lost("rosbridge closed the WebSocket (" + statusCode + (reason.isEmpty() ? "" : " " + reason) + ")");
                return null;
            }

            @Override
            public void onError(WebSocket webSocket, Throwable error) {
                lost("the WebSocket failed: " + (error.getMessage() == null ? error.toString() : error.getMessage()));
            }
        };
    }

    /** A fragment of a message: kept up to the size limit, the whole handled at its last; a longer one dropped. */
    void fragment(CharSequence data, boolean last) {
        if (!dropping && message.length() + data.length() > config.maxChars()) {
            dropping = true;
            message.setLength(0);
            bad("a message longer than " + config.maxChars() + " characters (rosbridge.maxMessage): dropped");
        }
        if (!dropping) {
            message.append(data);
        }
        if (last) {
            if (!dropping) {
                String whole = message.toString();
                message.setLength(0);
                received(whole);
            }
            dropping = false;
            if (message.capacity() > 1 << 20) {
                message.trimToSize();
            }
        }
    }

    private synchronized void lost(String why) {
        if (closed == null) {
            closed = why;
        }
    }
}
