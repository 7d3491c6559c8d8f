package org.usarsim.wss.model.obstacle;

import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.logging.Logger;
import org.usarsim.wss.model.DialogLayout;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.simulator.PollClock;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.model.simulator.PositionSource;
import org.usarsim.wss.model.simulator.SimulatorModel;
import org.usarsim.wss.world.WorldFileException;
import org.usarsim.wss.world.WorldWalls;

/**
 * The original's realisation of the manual's RayTracing idea: the DistanceOnly strength minus a
 * fixed attenuation per obstacle between the two robots, S = Pd0 - 10 N log10(d / d0) - k A. The
 * obstacle count k comes from the source of positions (USARSim's {@code GETOBS}, rosbridge's
 * occupancy grid on {@code rosbridge.map}), or from the walls of a world file
 * ({@code obstacle.walls}) counted here, and is cached per pair until either robot moves more than
 * the cache distance. Pessimistic: a pair with an unknown position or
 * count has NaN strength and may not connect. Registered robots absent from a non-empty position
 * list are kicked.
 */
public final class ObstaclePropagationModel extends SimulatorModel {

    private static final Logger LOG = Logger.getLogger(ObstaclePropagationModel.class.getName());

    private static final List<Setting> OBSTACLES = List.of(
            Setting.number("obstacle.attenuation", "Attenuation per obstacle", "6.325").from(0).unit("dB")
                    .help("The loss for each obstacle between two robots"),
            Setting.number("obstacle.cacheDistance", "Cache distance", "1.0").from(0).unit("m")
                    .help("How far a robot moves before the obstacles between it and the others are counted again"),
            Setting.text("obstacle.walls", "Walls file", "").orEmpty("the source's")
                    .help("A world file (the world server's format) whose walls the WSS counts between two robots itself;"
                            + " empty: the source counts them (GETOBS, or the grid on rosbridge.map)"),
            Setting.text("rosbridge.map", "Map topic", "/map").orEmpty("none")
                    .help("With positions from rosbridge: the nav_msgs/OccupancyGrid topic whose occupied cells are the walls"));

    /** Read at each start; volatile for the threads that ask for a strength. */
    private volatile double attenuation;
    /** The GETOBS cache: used by the poller only, made afresh at each start. */
    private ObstacleCounts counts;
    /** Whether the last batch of GETOBS went unanswered (used by the poller only). */
    private boolean getobsUnanswered;
    /** The walls of obstacle.walls, read at each start; null when the source counts. */
    private volatile WorldWalls ownWalls;
    /** Whether the source is USARSim's, whose counts are GETOBS answers. */
    private boolean usarsim;

    public ObstaclePropagationModel() {
    }

    /** A model whose poller takes its time from {@code clock}. */
    public ObstaclePropagationModel(PollClock clock) {
        super(clock);
    }

    /** The DistanceOnly model's layout with the Obstacles group. */
    @Override
    public DialogLayout dialogLayout() {
        return DialogLayout.DISTANCE_AND_OBSTACLES;
    }

    /** The simulator models' settings, then obstacle.attenuation and obstacle.cacheDistance. */
    @Override
    public List<Setting> settings() {
        List<Setting> all = new ArrayList<>(super.settings());
        all.addAll(OBSTACLES);
        return List.copyOf(all);
    }

    /** Reads the run's attenuation and cache distance, and the walls of obstacle.walls (refused when it cannot be read). */
    @Override
    protected void started(ModelSettings settings) throws ModelStartException {
        String file = settings.getString("obstacle.walls", "").strip();
        WorldWalls walls = null;
        if (!file.isEmpty()) {
            try {
                walls = WorldWalls.read(Path.of(file));
            } catch (WorldFileException | InvalidPathException e) {
                throw new ModelStartException("obstacle.walls: " + e.getMessage());
            }
            LOG.info("counting the obstacles between robots from the " + walls.walls().size() + " walls of " + file);
        }
        ownWalls = walls;
        usarsim = "usarsim".equals(settings.getString("positions", "usarsim"));
        attenuation = settings.getDouble("obstacle.attenuation", 0);
        counts = new ObstacleCounts(settings.getDouble("obstacle.cacheDistance", 0));
        getobsUnanswered = false;
    }

    /** The walls of obstacle.walls, when it names a file; else null: the source's. */
    @Override
    protected List<Wall> ownWalls() {
        WorldWalls walls = ownWalls;
        return walls == null ? null
                : walls.walls().stream().map(wall -> new Wall(wall.x1(), wall.y1(), wall.x2(), wall.y2())).toList();
    }

    @Override
    protected double strength(ReportedRobot a, ReportedRobot b, double obstacles) {
        return pathLoss().strength(a.distanceTo(b)) - obstacles * attenuation;
    }

    /** The range less the attenuation of the obstacles between: a pair behind two walls reaches less far. */
    @Override
    protected double range(double obstacles) {
        return pathLoss().range(obstacles * attenuation);
    }

    @Override
    protected boolean allowsUnknownRobots() {
        return false;
    }

    @Override
    protected boolean kicksRobotsAbsentFrom(Map<String, ReportedRobot> listed) {
        return !listed.isEmpty();
    }

    /**
     * Counts the walls of obstacle.walls, or asks the source, in one batch, for the counts of the
     * pairs whose count is unknown or no longer holds; an unanswered pair's count is unknown. A
     * source that answers none of a batch is reported once, and again once it answers.
     */
    @Override
    protected Map<RobotPair, Double> obstacleCounts(Map<String, ReportedRobot> listed, List<RobotPair> pairs,
            PositionSource simulator) throws IOException {
        ObstacleCounts known = counts;
        Set<RobotPair> current = new HashSet<>(pairs);
        known.retain(current::contains);
        List<RobotPair> stale = pairs.stream().filter(pair -> known.stale(pair, listed)).toList();
        if (stale.isEmpty()) {
            return known.counts(pairs);
        }
        WorldWalls walls = ownWalls;
        Map<RobotPair, Double> answers = walls == null ? simulator.obstacles(stale) : counted(walls, stale, listed);
        for (RobotPair pair : stale) {
            known.put(pair, answers.getOrDefault(pair, Double.NaN), listed);
        }
        if (answers.isEmpty() && !getobsUnanswered) {
            LOG.warning((usarsim ? "the simulator answers no GETOBS (" + stale.size() + " asked)"
                    : "rosbridge gives no occupancy grid on rosbridge.map (yet) and obstacle.walls names no file")
                    + ": pairs whose obstacle count is unknown cannot connect");
        } else if (!answers.isEmpty() && getobsUnanswered) {
            LOG.info(usarsim ? "the simulator answers GETOBS again" : "obstacles counted on rosbridge's occupancy grid");
        }
        getobsUnanswered = answers.isEmpty();
        return known.counts(pairs);
    }

    /** The walls of obstacle.walls between each pair, as the world server counts them for GETOBS. */
    private static Map<RobotPair, Double> counted(WorldWalls walls, List<RobotPair> pairs, Map<String, ReportedRobot> listed) {
        Map<RobotPair, Double> counted = new java.util.HashMap<>();
        for (RobotPair pair : pairs) {
            ReportedRobot a = listed.get(pair.first());
            ReportedRobot b = listed.get(pair.second());
            counted.put(pair, (double) walls.crossings(a.x(), a.y(), b.x(), b.y()));
        }
        return counted;
    }
}
