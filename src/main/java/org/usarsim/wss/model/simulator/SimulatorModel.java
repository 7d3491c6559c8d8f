package org.usarsim.wss.model.simulator;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import org.usarsim.wss.model.DialogLayout;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.Wall;

/**
 * A propagation model driven by robot positions polled from a {@link PositionSource}: a
 * USARSim-compatible simulator's position socket, or rosbridge ({@code positions}). Every interval
 * it asks the source where the robots are; then it kicks the registered robots the source no longer
 * lists or whose battery is empty, and breaks or resumes every pair of listed robots by its
 * strength (events only on change). When the source goes silent, answers late or sends garbage,
 * the model says so once, keeps the last known link state and reconnects with a growing pause.
 *
 * <p>Subclasses give the strength of a pair; the rest is here, in one place.
 */
public abstract class SimulatorModel extends PollingModel {

    private static final long MAX_BACKOFF_MS = 10_000;

    /** Where the positions come from: the values of {@code positions}. */
    public static final String USARSIM = "usarsim";
    public static final String ROSBRIDGE = "rosbridge";

    /**
     * The settings of every simulator model: where the positions come from (positions.*, the
     * simulator's socket usarsim.*, or rosbridge.*), the path loss, the link stability.
     */
    static final List<Setting> SETTINGS = List.of(
            Setting.choice("positions", "Positions from", USARSIM, List.of(USARSIM, ROSBRIDGE))
                    .help("Where the robots' positions come from: a USARSim-compatible position socket (usarsim.*)"
                            + " or a rosbridge WebSocket (rosbridge.*, docs/ros.md)"),
            Setting.integer("positions.interval", "Poll interval", 1000).from(100).to(60000).unit("ms").alias("usarsim.interval")
                    .help("Milliseconds between two applications of the robots' positions: a GETPOS,"
                            + " or rosbridge's throttle_rate (formerly usarsim.interval)"),
            Setting.host("usarsim.host", "Host", "127.0.0.1")
                    .help("The machine of the simulator's position socket: a host name or an IP address"),
            Setting.integer("usarsim.port", "Port", 7435).from(1).to(65535).noun("a port number")
                    .help("The simulator's position port, 7435 as a rule; not 3000, which is USARSim's robot port"),
            Setting.integer("usarsim.timeout", "Timeout", 2000).from(100).to(60000).unit("ms")
                    .help("Milliseconds to wait for the simulator's answer"),
            Setting.text("rosbridge.url", "URL", RosbridgeConfig.DEFAULT_URL)
                    .help("The rosbridge server's WebSocket: ws://HOST:PORT (rosbridge_server's default port is 9090)"),
            Setting.text("rosbridge.topic", "Topic", RosbridgeConfig.DEFAULT_TOPIC)
                    .help("The topic of the poses: /gazebo/model_states, /tf, or a per-robot one such as /{robot}/odom"),
            Setting.choice("rosbridge.type", "Message type", "", RosbridgeConfig.TYPES).orEmpty("by the topic")
                    .help("The topic's message type, where its name does not tell"),
            Setting.text("rosbridge.frame", "Frame", RosbridgeConfig.DEFAULT_FRAME)
                    .help("On /tf: the frame positions are in; each robot's chain of transforms is composed up to it"),
            Setting.text("rosbridge.names", "Names", "").orEmpty("the WSS names")
                    .help("WSS robot names to model names or frames, WSS=MODEL separated by commas (Scout=scout_1);"
                            + " others by their WSS name, or {robot}/base_link on /tf"),
            Setting.integer("rosbridge.stale", "Stale limit", 0).from(0).to(600000).unit("ms").note("0: 3 poll intervals")
                    .help("A robot whose pose is older is unlisted (kicked); nothing at all for this long: rosbridge is silent"),
            Setting.integer("rosbridge.grace", "Grace", RosbridgeConfig.DEFAULT_GRACE_MS).from(RosbridgeConfig.LEAST_GRACE_MS)
                    .to(600000).unit("ms")
                    .help("How long a registered robot's first pose is waited for before it is kicked as unlisted"
                            + " (its own topic subscribed as it registers, its publisher started late), and a new connection's"
                            + " first message before rosbridge counts as silent"),
            Setting.integer("rosbridge.maxMessage", "Largest message", 16).from(1).to(1024).unit("MiB")
                    .help("A longer message from rosbridge (its fragments together) is dropped with a line in the log"),
            Setting.number("distance.cutoff", "Cutoff", "-93").unit("dBm")
                    .help("Below this signal strength two robots cannot talk; -93 dBm is a property of the channel, best left as it is"),
            Setting.number("distance.pd0", "Pd0", "-49.67").unit("dBm").help("The signal strength at distance d0"),
            Setting.number("distance.n", "N", "1").above(0)
                    .help("The attenuation factor of the environment: how fast the signal fades with distance"),
            Setting.number("distance.d0", "d0", "2").above(0).unit("m").help("The distance at which the strength is Pd0"),
            Setting.number("distance.margin", "Margin", "0").from(0).unit("dB")
                    .help("A broken link resumes only when the strength is above Cutoff + Margin, so that a pair at the edge does not flap"),
            Setting.number("distance.holdTime", "Hold time", "0").from(0).unit("s")
                    .help("A link stays broken, or resumed, at least this many seconds before it changes again"));

    /** The path loss of the declared defaults, until the first start. */
    private static final PathLoss DEFAULT_PATH_LOSS;

    static {
        try {
            DEFAULT_PATH_LOSS = SimulatorConfig.read(SETTINGS, Map.of()).pathLoss();
        } catch (ModelStartException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    private final PollClock clock;

    /** The configuration of the current run (or the last one); null before the first start. */
    private volatile SimulatorConfig config;
    /** What the last poll learned and decided, swapped whole: GETSS and accepts read it. */
    private volatile PollSnapshot snapshot = PollSnapshot.empty(new LinkStates(0, 0, 0), 0);
    /** The polling of the current run, from a start to its shutdown; null while stopped. */
    private volatile Poller poller;
    /** The simulator's walls as its connection last gave them (GETWALLS); empty when it gives none. */
    private volatile List<Wall> walls = List.of();

    /** A model on the machine's clock. */
    protected SimulatorModel() {
        this(PollClock.SYSTEM);
    }

    /** A model whose poller takes its time from {@code clock} and waits with it. */
    protected SimulatorModel(PollClock clock) {
        this.clock = Objects.requireNonNull(clock, "clock");
    }

    /** The simulator's connection (usarsim.*), the path loss (distance.*) and the link stability (distance.margin, distance.holdTime). */
    @Override
    public List<Setting> settings() {
        return SETTINGS;
    }

    /**
     * The DistanceOnly model's layout, which shows every key of {@link #SETTINGS}; a subclass
     * whose declaration lacks one of them gets the generated dialog.
     */
    @Override
    public DialogLayout dialogLayout() {
        return DialogLayout.DISTANCE;
    }

    /** Checks and freezes the configuration, opens the source of positions and starts polling it. */
    @Override
    public synchronized void start() throws ModelStartException {
        if (poller != null) {
            return;
        }
        RobotLinkModel server = server();
        SimulatorConfig run = SimulatorConfig.read(settings(), given());
        started(run.values());
        PositionSource.Opener opener = run.opener(clock);
        PositionSource source = null;
        IOException unreachable = null;
        try {
            source = opener.open();
        } catch (IOException | RuntimeException e) {
            if (!opener.startsSilent()) {
                throw new ModelStartException("cannot reach the simulator at " + run.where() + " (" + e.getMessage() + ")", e);
            }
            unreachable = e instanceof IOException io ? io : new IOException(e.getMessage(), e);
        }
        config = run;
        LinkStates links = new LinkStates(run.pathLoss().cutoff(), run.margin(), run.holdSeconds());
        snapshot = PollSnapshot.empty(links, clock.nanoTime());
        List<Wall> own = ownWalls();
        walls = own == null ? List.of() : List.copyOf(own);
        PathLoss pathLoss = run.pathLoss();
        log.info(name() + (run.rosbridge() != null ? " takes positions from " : " polls the simulator at ") + run.where()
                + " every " + run.intervalMs() + " ms; range "
                + metres(pathLoss.range()) + " (cutoff " + pathLoss.cutoff() + " dBm"
                + (run.margin() > 0 ? ", margin " + run.margin() + " dB" : "")
                + (run.holdSeconds() > 0 ? ", hold time " + run.holdSeconds() + " s" : "") + ")");
        poller = new Poller(server, run, opener, source, unreachable);
    }

    /** Stops polling; a poll under way is abandoned (its connection closed) and acts on nothing more. */
    @Override
    public void shutdown() {
        Poller stopping;
        synchronized (this) {
            stopping = poller;
            poller = null;
        }
        if (stopping != null) {
            stopping.stop();
        }
    }

    @Override
    public boolean isActive() {
        return poller != null;
    }

    /** The strength from the last known positions: NaN while either robot's position is unknown. */
    @Override
    public double getSignalStrengthForPair(String from, String to) {
        PollSnapshot known = snapshot;
        ReportedRobot a = known.positions().get(from);
        ReportedRobot b = known.positions().get(to);
        return a == null || b == null ? Double.NaN : strength(a, b, known.obstacles(RobotPair.of(from, to)));
    }

    /**
     * The pair's link state as last decided; for a pair not decided yet, its strength against the
     * cutoff, or {@link #allowsUnknownRobots()} while a position is unknown.
     */
    @Override
    public boolean connectionIsPossibleForPair(String from, String to) {
        PollSnapshot known = snapshot;
        RobotPair pair = RobotPair.of(from, to);
        Boolean live = known.links().live(pair);
        if (live != null) {
            return live;
        }
        ReportedRobot a = known.positions().get(from);
        ReportedRobot b = known.positions().get(to);
        return a == null || b == null ? allowsUnknownRobots() : strength(a, b, known.obstacles(pair)) >= pathLoss().cutoff();
    }

    /** Where the last poll found the robot; empty before it or when the simulator did not list it. */
    @Override
    public Optional<Position> positionOf(String robot) {
        ReportedRobot known = snapshot.positions().get(robot);
        return known == null ? Optional.empty() : Optional.of(new Position(known.x(), known.y(), known.z()));
    }

    /**
     * The distance at which the pair's strength reaches the cutoff, with the obstacle count between
     * them as the last poll counted it (none when not counted, and between a robot and itself: the
     * range through open space).
     */
    @Override
    public double rangeFor(String from, String to) {
        double obstacles = from.equals(to) ? Double.NaN : snapshot.obstacles(RobotPair.of(from, to));
        return range(Double.isNaN(obstacles) ? 0 : obstacles);
    }

    /** The walls the simulator gave ({@code GETWALLS}, which only the world server answers); empty otherwise. */
    @Override
    public List<Wall> walls() {
        return walls;
    }

    /** The cutoff of the current run (the declared default before the first start). */
    @Override
    public double cutoff() {
        return pathLoss().cutoff();
    }

    // ---- what a subclass decides ----

    /** The distance at which the strength with this many obstacles between reaches the cutoff: the path loss's range by default. */
    protected double range(double obstacles) {
        return pathLoss().range();
    }

    /**
     * The strength in dBm between two robots the simulator lists, with the obstacle count between
     * them as {@link #obstacleCounts} gave it (NaN when not counted); NaN when it cannot be known.
     */
    protected abstract double strength(ReportedRobot a, ReportedRobot b, double obstacles);

    /** Whether a robot with no known position may connect. */
    protected abstract boolean allowsUnknownRobots();

    /** Whether registered robots absent from this position list are kicked. */
    protected abstract boolean kicksRobotsAbsentFrom(Map<String, ReportedRobot> listed);

    /**
     * Called at every poll before the pairs are decided, with the pairs to decide: the obstacle
     * count of each pair that has one. Published with this poll's positions. None by default.
     */
    protected Map<RobotPair, Double> obstacleCounts(Map<String, ReportedRobot> listed, List<RobotPair> pairs,
            PositionSource source) throws IOException {
        return Map.of();
    }

    /**
     * Called at every start, before the source is opened, with the run's checked settings (every
     * declared key): a subclass reads its own and forgets what the last run learned; it may refuse
     * the start.
     */
    protected void started(ModelSettings settings) throws ModelStartException {
    }

    /**
     * The walls of the model's own (the Obstacle model's {@code obstacle.walls}), read at the start,
     * which the map shows and a recording keeps instead of the source's; null (the default) for
     * the source's.
     */
    protected List<Wall> ownWalls() {
        return null;
    }

    /** The path loss of the current run (the declared defaults before the first start). */
    protected final PathLoss pathLoss() {
        SimulatorConfig run = config;
        return run != null ? run.pathLoss() : DEFAULT_PATH_LOSS;
    }

    // ---- the poller ----

    /**
     * One run of polling, from a start to its shutdown: its own thread, configuration, connection
     * and trouble state, so that a run that is slow to stop can never touch the next one's.
     */
    private final class Poller implements Runnable {

        private final RobotLinkModel server;
        private final SimulatorConfig run;
        private final PositionSource.Opener opener;
        private final Thread thread;
        private volatile boolean stopped;
        private volatile PositionSource connection;
        /** Why the simulator is unusable since {@link #troubleSince}; null while it answers. */
        private String trouble;
        private long troubleSince;
        /** A failure that is not the simulator's, already logged; null after a good poll. */
        private String failure;
        /** The source's walls as {@link #walls} holds them: learnt again when the source gives others. */
        private List<Wall> wallsFrom;
        /** Whether this run said that the simulator gives no walls. */
        private boolean saidNoWalls;

        /** Polls {@code source}; when it is null (unreachable at the start, for {@code unreachable}), opens one first. */
        Poller(RobotLinkModel server, SimulatorConfig run, PositionSource.Opener opener, PositionSource source, IOException unreachable) {
            this.server = server;
            this.run = run;
            this.opener = opener;
            this.connection = source;
            if (unreachable != null) {
                lost(unreachable);
            }
            thread = new Thread(this, name() + " poller");
            thread.setDaemon(true);
            thread.start();
        }

        void stop() {
            stopped = true;
            thread.interrupt();
            close();
            try {
                thread.join(TimeUnit.SECONDS.toMillis(5));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        @Override
        public void run() {
            long backoffMs = run.intervalMs();
            long next = clock.nanoTime();
            if (trouble != null) {
                // Unreachable at the start: the first attempt again after a pause, as after a loss.
                next += backoffMs * 1_000_000L;
                backoffMs = nextBackoff(backoffMs, run.intervalMs());
            }
            try {
                while (pause(next)) {
                    next = clock.nanoTime() + run.intervalMs() * 1_000_000L;
                    try {
                        PositionSource simulator = connection;
                        if (simulator == null) {
                            simulator = opener.open();
                            connection = simulator;
                        }
                        if (poll(simulator)) {
                            back();
                            backoffMs = run.intervalMs();
                        }
                    } catch (IOException e) {
                        if (stopped) {
                            return;
                        }
                        lost(e);
                        close();
                        next = clock.nanoTime() + backoffMs * 1_000_000L;
                        backoffMs = nextBackoff(backoffMs, run.intervalMs());
                    } catch (RuntimeException | Error e) {
                        failed(e);
                    }
                }
            } finally {
                close();
            }
        }

        /** Waits until {@code deadline}; false when the run was stopped meanwhile. */
        private boolean pause(long deadline) {
            while (!stopped && deadline - clock.nanoTime() > 0) {
                try {
                    clock.sleepUntil(deadline);
                } catch (InterruptedException e) {
                    return false;
                }
            }
            return !stopped;
        }

        /**
         * One poll: positions, kicks, obstacle counts, then every pair of listed robots decided,
         * published, broken or resumed. False when the source gave none, being just opened (the
         * poll acts on nothing).
         */
        private boolean poll(PositionSource simulator) throws IOException {
            List<String> registered = server.getListOfRegisteredRobots();
            Map<String, ReportedRobot> listed = simulator.positions(registered);
            if (stopped || listed == null) {
                return false;
            }
            // A robot the source still waits for is neither kicked nor decided: as if it had not registered yet.
            Set<String> waited = simulator.waitedFor();
            List<String> registeredBefore = waited.isEmpty() ? registered
                    : registered.stream().filter(robot -> !waited.contains(robot)).toList();
            if (ownWalls() == null) {
                learnWalls(simulator);
            }
            applyPoll(new Poll(registeredBefore, listed, kicksRobotsAbsentFrom(listed), "simulator", "", walls, () -> stopped),
                    present -> decide(present, listed, simulator));
            failure = null;
            return true;
        }

        /** The obstacle counts, then every pair of the present robots decided and published (GETSS reads it); null when stopped. */
        private List<ModelPoll.Pair> decide(List<String> present, Map<String, ReportedRobot> listed, PositionSource simulator)
                throws IOException {
            Map<RobotPair, Double> obstacles = obstacleCounts(listed, PollStep.pairs(present), simulator);
            if (stopped) {
                return null;
            }
            PollStep.Decision decision = PollStep.decide(present, listed, obstacles, clock.nanoTime(), snapshot.links(),
                    SimulatorModel.this::strength);
            // Only now, whole: a GETSS meanwhile answers from the last poll's positions and counts.
            snapshot = decision.snapshot();
            List<ModelPoll.Pair> pairs = new ArrayList<>(decision.links().size());
            for (PollStep.Link link : decision.links()) {
                RobotPair pair = link.pair();
                pairs.add(new ModelPoll.Pair(pair.first(), pair.second(), link.strength(), obstacles.getOrDefault(pair, Double.NaN),
                        link.live()));
            }
            return pairs;
        }

        /** Takes the source's walls once they are known, and says what they are, each time it gives others. */
        private void learnWalls(PositionSource simulator) {
            List<Wall> given = simulator.walls();
            if (given == null || given == wallsFrom) {
                return;
            }
            wallsFrom = given;
            walls = given;
            if (simulator.wallsProblem() != null) {
                log.warning("the simulator at " + run.where() + " gave its walls in a reply that cannot be read ("
                        + simulator.wallsProblem() + "): the map shows none");
            } else if (given.isEmpty()) {
                if (!saidNoWalls) {
                    log.info("the simulator at " + run.where() + " gives no walls" + (run.rosbridge() == null
                            ? " (USARSim does not answer GETWALLS)" : "") + ": the map shows none");
                    saidNoWalls = true;
                }
            } else {
                log.info("the simulator at " + run.where() + " gives " + given.size() + " walls");
            }
        }

        private void lost(IOException e) {
            String reason = e.getMessage() == null ? e.toString() : e.getMessage();
            if (trouble == null) {
                troubleSince = clock.nanoTime();
                log.warning("lost the simulator at " + run.where() + ": " + reason
                        + "; keeping the last known link state and reconnecting");
            } else if (!reason.equals(trouble)) {
                log.fine("the simulator at " + run.where() + " is still unusable: " + reason);
            }
            trouble = reason;
        }

        private void back() {
            if (trouble != null) {
                long seconds = TimeUnit.NANOSECONDS.toSeconds(clock.nanoTime() - troubleSince);
                log.info("the simulator at " + run.where() + " answers again after " + seconds + " s");
                trouble = null;
            }
        }

        /** A failure that is not the simulator's (a bug, a listener that throws): logged once, then polling goes on. */
        private void failed(Throwable e) {
            if (failure == null) {
                log.log(Level.WARNING, name() + ": a poll failed (" + e + "); polling goes on", e);
            }
            failure = e.toString();
        }

        private void close() {
            PositionSource open = connection;
            connection = null;
            if (open != null) {
                open.close();
            }
        }
    }

    /** The pause after a failed attempt that follows one of {@code backoffMs}: doubled, up to 10 s (or the interval, if longer). */
    static long nextBackoff(long backoffMs, int intervalMs) {
        return Math.min(backoffMs * 2, Math.max(MAX_BACKOFF_MS, intervalMs));
    }
}
