package org.usarsim.wss.model.simulator;

import java.io.IOException;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import org.usarsim.wss.model.DialogLayout;
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

    /** The path loss of the declared defaults, until the first start. */
    private static final PathLoss DEFAULT_PATH_LOSS;

    static {
        try {
            DEFAULT_PATH_LOSS = SimulatorConfig.read(SimulatorSettings.ALL, Map.of()).pathLoss();
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
    private volatile SimulatorPoller poller;
    /** The shadowing of the current run (shadowing.*), added to every strength; none before the first start. */
    private volatile Shadowing shadowing = Shadowing.NONE;
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
        return SimulatorSettings.ALL;
    }

    /**
     * The DistanceOnly model's layout, which shows every key of {@link SimulatorSettings#ALL}; a subclass
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
        shadowing = Shadowing.of(run.values());
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
        poller = new SimulatorPoller(this, server, run, opener, source, unreachable);
    }

    /** Stops polling; a poll under way is abandoned (its connection closed) and acts on nothing more. */
    @Override
    public void shutdown() {
        SimulatorPoller stopping;
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
        return a == null || b == null ? Double.NaN : signal(a, b, known.obstacles(RobotPair.of(from, to)));
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
        return a == null || b == null ? allowsUnknownRobots() : signal(a, b, known.obstacles(pair)) >= pathLoss().cutoff();
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

    /**
     * Whether a robot with no known position may connect: not by default (a model whose verdict
     * needs both positions: the walls between, the power at the distance).
     */
    protected boolean allowsUnknownRobots() {
        return false;
    }

    /**
     * Whether registered robots absent from this position list are kicked: by default when the list
     * names anyone (an empty list is a simulator that lists nobody yet).
     */
    protected boolean kicksRobotsAbsentFrom(Map<String, ReportedRobot> listed) {
        return !listed.isEmpty();
    }

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

    // ---- what the poller reads and publishes ----

    /** The strength the model decides by: the subclass's {@link #strength} plus the run's shadowing (docs/models.md). */
    final double signal(ReportedRobot a, ReportedRobot b, double obstacles) {
        return strength(a, b, obstacles) + shadowing.db(a, b);
    }

    PollClock clock() {
        return clock;
    }

    /** What the last poll learned and decided. */
    PollSnapshot snapshot() {
        return snapshot;
    }

    /** Publishes a poll's decision, whole: GETSS and accepts read it from now. */
    void published(PollSnapshot decided) {
        snapshot = decided;
    }

    /** Takes the walls the source gave. */
    void walls(List<Wall> given) {
        walls = given;
    }

    /** The path loss of the current run (the declared defaults before the first start). */
    protected final PathLoss pathLoss() {
        SimulatorConfig run = config;
        return run != null ? run.pathLoss() : DEFAULT_PATH_LOSS;
    }

    /** The pause after a failed attempt that follows one of {@code backoffMs}: doubled, up to 10 s (or the interval, if longer). */
    static long nextBackoff(long backoffMs, int intervalMs) {
        return Math.min(backoffMs * 2, Math.max(MAX_BACKOFF_MS, intervalMs));
    }
}
