package org.usarsim.wss.model.simulator;

import java.io.IOException;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.time.Duration;
import java.util.Collection;
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
import org.usarsim.wss.ros.JsonNode;
import org.usarsim.wss.ros.MessageType;
import org.usarsim.wss.ros.OccupancyGrid;
import org.usarsim.wss.ros.PoseDecoder;
import org.usarsim.wss.ros.RobotPose;
import org.usarsim.wss.ros.RosFrame;

/**
 * Positions from a rosbridge v2 server (docs/ros.md): one WebSocket (the JDK's client), the
 * subscriptions of {@link TopicRequests} (the poses' topic, {@code /tf_static} beside {@code /tf},
 * or one topic per robot as robots register; the map's grid). Messages arrive on the WebSocket's
 * thread, whole once {@link MessageAssembler} has put their pieces together, are decoded by
 * {@link PoseDecoder} and kept in the {@link PoseTable}, the latest per robot; each poll takes what
 * is fresh, and learns which registered robots are still waited for and whether the source is
 * silent. A grid on the map topic goes to {@link GridCounts}. A message that cannot be read is one
 * line in the log, limited as warnings are, and changes nothing but the silence.
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
        /** The problems of messages that cannot be read said so far: each said once (at most {@link #PROBLEMS} kept). */
        private final Set<String> saidProblems = new HashSet<>();
        static final int PROBLEMS = 64;

        /** Whether a problem is said now: the first time it is seen in the run. */
        synchronized boolean sayProblem(String problem) {
            return saidProblems.size() < PROBLEMS ? saidProblems.add(problem) : !saidProblems.contains(problem);
        }
    }

    private final RosbridgeConfig config;
    private final PollClock clock;
    private final RunNotes notes;
    private final LogLimiter limiter;
    private final PoseDecoder decoder;
    private final MessageAssembler assembler;
    private final GridCounts grid = new GridCounts();

    // Shared between the WebSocket's thread and the poller: under this object's lock.
    private final PoseTable table;
    private final TopicRequests topics = new TopicRequests();
    /** Why the WebSocket is closed; null while it is open. */
    private String closed;
    /** The registered robots the last poll found still waited for. */
    private Set<String> waitedFor = Set.of();
    /** What the last poll listed, where the obstacles between are counted (the poller's only). */
    private Map<String, ReportedRobot> lastListed = Map.of();

    private WebSocket socket;
    private CompletableFuture<WebSocket> sending = CompletableFuture.completedFuture(null);

    RosbridgeSource(RosbridgeConfig config, PollClock clock, RunNotes notes, LogLimiter limiter) {
        this.config = config;
        this.clock = clock;
        this.notes = notes;
        this.limiter = limiter;
        this.assembler = new MessageAssembler(config.maxChars(), this::bad, this::received);
        this.decoder = new PoseDecoder(config.type(), config.frame(),
                config.perRobot() ? config.topic() : PoseDecoder.DEFAULT_ROBOT_TOPIC, assembler.limits());
        this.table = new PoseTable(TimeUnit.MILLISECONDS.toNanos(config.staleMs()), TimeUnit.MILLISECONDS.toNanos(config.graceMs()),
                clock.nanoTime());
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

    /** Takes the open WebSocket and subscribes: to the poses' topics (a per-robot one at each poll), to the grid's. */
    void attach(WebSocket webSocket) {
        synchronized (this) {
            socket = webSocket;
        }
        if (!config.perRobot()) {
            TopicRequests.poses(config.topic(), config.type()).forEach(this::subscribe);
        }
        if (config.mapTopic() != null) {
            subscribe(TopicRequests.map(config.mapTopic(), config.intervalMs()));
        }
    }

    private void subscribe(TopicRequests.Topic topic) {
        synchronized (this) {
            if (topics.add(topic, clock.nanoTime())) {
                send(topic.request());
            }
        }
    }

    /** Sends a request, after those before it. Under this object's lock. */
    private void send(String text) {
        WebSocket open = socket;
        if (open != null) {
            // One send at a time: the next goes once the last is done, or failed (the WebSocket's close says why).
            sending = sending.handle((done, failed) -> done).thenCompose(done -> open.sendText(text, true));
        }
    }

    @Override
    public Map<String, ReportedRobot> positions(List<String> registered) throws IOException {
        boolean asking = !config.perRobot() || !registered.isEmpty() || !config.names().listed().isEmpty();
        if (config.perRobot()) {
            Set<String> robots = new LinkedHashSet<>(config.names().listed().keySet());
            robots.addAll(registered);
            robots.forEach(robot -> subscribe(TopicRequests.onePublisher(config.topicOf(robot), config.type())));
        }
        Map<String, ReportedRobot> listed;
        List<TopicRequests.Topic> quiet;
        long now = clock.nanoTime();
        synchronized (this) {
            if (closed != null) {
                throw new IOException(closed);
            }
            quiet = topics.quiet(now, TimeUnit.MILLISECONDS.toNanos(RosbridgeConfig.QUIET_MS));
            topics.askAgain(now, TimeUnit.MILLISECONDS.toNanos(RosbridgeConfig.QUIET_MS)).forEach(topic -> send(topic.request()));
            String silence = asking ? table.silence(now, config.url().toString()) : null;
            if (silence != null) {
                throw new IOException(silence);
            }
            listed = table.listed(now);
            waitedFor = table.waitedFor(registered, now);
        }
        for (TopicRequests.Topic topic : quiet) {
            boolean first;
            synchronized (notes) {
                first = notes.saidQuiet.add(topic.name());
            }
            if (first) {
                LOG.warning("rosbridge at " + config.url() + " sent nothing on " + topic.name() + " (" + topic.type() + ") for "
                        + RosbridgeConfig.QUIET_MS / 1000 + " s since it was subscribed: is the topic or its type wrong?"
                        + " (rosbridge answers no error for either)");
            }
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

    /** The registered robots the last poll found waited for: their first pose may still come within the grace. */
    @Override
    public synchronized Set<String> waitedFor() {
        return waitedFor;
    }

    /** One whole message from rosbridge: poses kept, a fragment put with its others, anything else said or passed over. */
    void received(String text) {
        long now = clock.nanoTime();
        RosFrame frame;
        Map<String, RobotPose> poses = new LinkedHashMap<>();
        try {
            frame = RosFrame.parse(text, assembler.limits());
            if ("fragment".equals(frame.op())) {
                assembler.fragment(frame.root());
                return;
            }
            if (!frame.isPublish()) {
                said(frame);
                return;
            }
            TopicRequests.Topic faster;
            synchronized (this) {
                faster = topics.came(frame.topic(), now);
                if (faster != null) {
                    send(faster.request());
                }
            }
            if (faster != null) {
                LOG.info("rosbridge at " + config.url() + " sends more than " + TopicRequests.MOST_AS_THEY_COME + " messages a second on "
                        + faster.name() + ": asked for again with at most one each " + faster.throttleMs() + " ms, the newest");
            }
            if (frame.topic() != null && frame.topic().equals(config.mapTopic())) {
                tookGrid(OccupancyGrid.of(frame.msg()));
                return;
            }
            for (RobotPose pose : decoder.decode(frame)) {
                String robot = config.names().wss(pose.name());
                if (robot != null) {
                    poses.put(robot, pose);
                }
            }
        } catch (JsonException | RuntimeException e) {
            bad("a message that cannot be read (" + e.getMessage() + ")");
            return;
        }
        synchronized (this) {
            table.took(poses, config.type() == MessageType.MODEL_STATES, !topics.latched(frame.topic()), now);
        }
    }

    /** A grid from the map topic: counted on from now. */
    private void tookGrid(OccupancyGrid taken) {
        grid.took(taken);
        boolean firstGrid;
        synchronized (notes) {
            firstGrid = !notes.saidGrid;
            notes.saidGrid = true;
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

    /**
     * What cannot be read or assembled: no sign of life; said once in the run for each problem
     * (the same problem again is a FINE line), within the limit on warnings.
     */
    private void bad(String what) {
        synchronized (this) {
            table.unreadable();
        }
        String line = "rosbridge at " + config.url() + " sent " + what + ": keeping the last good positions";
        if (notes.sayProblem(what)) {
            limiter.log(LOG, Level.WARNING, "bad rosbridge messages", null, line + " (said once; the same again is logged at FINE)", null);
        } else {
            LOG.fine(line);
        }
    }

    /** The grid's walls once one came on the map topic (null until then); none without a map topic. */
    @Override
    public List<Wall> walls() {
        return config.mapTopic() == null ? List.of() : grid.walls();
    }

    @Override
    public String wallsProblem() {
        return null;
    }

    /** The walls of the grid between each pair where the last poll listed them; none before a grid came. */
    @Override
    public Map<RobotPair, Double> obstacles(Collection<RobotPair> pairs) {
        return grid.between(pairs, lastListed);
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

    /** A piece of a WebSocket message, as the WebSocket's thread hands it over. */
    void fragment(CharSequence data, boolean last) {
        assembler.piece(data, last);
    }

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

    private synchronized void lost(String why) {
        if (closed == null) {
            closed = why;
        }
    }
}
