package org.usarsim.wss.model.obstacle;

import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.logging.Logger;
import java.util.stream.Collectors;
import org.usarsim.wss.model.DialogLayout;
import org.usarsim.wss.model.ModelInputException;
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
                    .help("A world file (the world server's format) or a Gazebo SDF world whose walls the WSS counts between two robots itself;"
                            + " empty: the source counts them (GETOBS, or the grid on rosbridge.map)"),
            Setting.text("rosbridge.map", "Map topic", "/map").orEmpty("none")
                    .help("With positions from rosbridge: the nav_msgs/OccupancyGrid topic whose occupied cells are the walls"),
            Setting.text("obstacle.materials", "Wall materials", WallSettings.MATERIALS).orEmpty("every wall the attenuation")
                    .alias("wss.walls.materials")
                    .help("An SDF world's walls: GLOB=MATERIAL, ... on model, link or collision names, the first match wins"),
            Setting.text("obstacle.loss", "Loss per material", WallSettings.LOSSES).orEmpty("none").alias("wss.walls.loss")
                    .help("The loss of one wall crossed of each material, MATERIAL:DB, ...; a wall of no material loses the attenuation"),
            Setting.text("obstacle.heightBand", "Robots' height band", WallSettings.BAND).unit("m")
                    .help("An SDF world's boxes are walls when their height meets LOW..HIGH metres"));

    /** Read at each start; volatile for the threads that ask for a strength. */
    private volatile double attenuation;
    /** The GETOBS cache: used by the poller only, made afresh at each start. */
    private ObstacleCounts counts;
    /** Whether the last batch of GETOBS went unanswered (used by the poller only). */
    private boolean getobsUnanswered;
    /** The walls of obstacle.walls, read at each start; null when the source counts. */
    private volatile WorldWalls ownWalls;
    /** Their losses by material (obstacle.loss, the attenuation for a wall of none); null when the source counts. */
    private WallLoss wallLoss;
    /** The walls and losses the last poll counted itself, by pair: the wall-loss term reads them. */
    private volatile Map<RobotPair, WallLoss.Crossing> crossings = Map.of();
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

    /**
     * Reads the run's attenuation and cache distance, and the walls of obstacle.walls with their
     * materials' losses (refused when it cannot be read, or a material has no loss).
     */
    @Override
    protected void started(ModelSettings settings) throws ModelStartException {
        String file = settings.getString("obstacle.walls", "").strip();
        attenuation = settings.getDouble("obstacle.attenuation", 0);
        WorldWalls walls = null;
        WallLoss losses = null;
        if (!file.isEmpty()) {
            WallSettings read = WallSettings.of(settings);
            try {
                walls = read.walls(Path.of(file));
            } catch (WorldFileException | InvalidPathException e) {
                throw new ModelStartException("obstacle.walls: " + e.getMessage());
            }
            try {
                losses = new WallLoss(walls, read.losses(), attenuation);
            } catch (IllegalArgumentException e) {
                throw new ModelInputException("obstacle.walls: " + file + " has " + e.getMessage());
            }
            walls.notes().forEach(note -> LOG.info("obstacle.walls: " + file + ": " + note));
            LOG.info("counting the obstacles between robots from the " + walls.count() + " walls of " + file
                    + (walls.materials().equals(List.of("")) || walls.materials().isEmpty() ? ""
                    : " (" + walls.materials().stream().map(m -> m.isEmpty() ? "no material" : m).collect(Collectors.joining(", ")) + ")"));
        }
        ownWalls = walls;
        wallLoss = losses;
        crossings = Map.of();
        usarsim = "usarsim".equals(settings.getString("positions", "usarsim"));
        counts = new ObstacleCounts(settings.getDouble("obstacle.cacheDistance", 0));
        getobsUnanswered = false;
    }

    /** The walls of obstacle.walls, when it names a file; else null: the source's. */
    @Override
    protected List<Wall> ownWalls() {
        WorldWalls walls = ownWalls;
        return walls == null ? null
                : walls.walls().stream().map(wall -> new Wall(wall.x1(), wall.y1(), wall.x2(), wall.y2(), wall.material())).toList();
    }

    @Override
    protected double strength(ReportedRobot a, ReportedRobot b, double obstacles) {
        return pathLoss().strength(a.distanceTo(b)) - wallLoss(RobotPair.of(a.name(), b.name()), obstacles);
    }

    /**
     * The wall-loss term, in dB: the losses of the walls of obstacle.walls the last poll counted
     * between the pair, by material; else (the source's counts, or a count of another poll read
     * while the next one is being published) the count times the attenuation, the original's term.
     * NaN when the count is unknown.
     */
    double wallLoss(RobotPair pair, double obstacles) {
        WallLoss.Crossing counted = crossings.get(pair);
        return counted != null && counted.count() == obstacles ? counted.lossDb() : obstacles * attenuation;
    }

    /** The range less the attenuation of the obstacles between: a pair behind two walls reaches less far. */
    @Override
    protected double range(double obstacles) {
        return pathLoss().range(obstacles * attenuation);
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
        WallLoss walls = wallLoss;
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

    /**
     * The walls of obstacle.walls between each stale pair, as the world server counts them for
     * GETOBS, and their losses, kept for the wall-loss term with those of the pairs still fresh.
     */
    private Map<RobotPair, Double> counted(WallLoss walls, List<RobotPair> pairs, Map<String, ReportedRobot> listed) {
        Map<RobotPair, Double> counted = new HashMap<>();
        Map<RobotPair, WallLoss.Crossing> all = new HashMap<>(crossings);
        all.keySet().retainAll(counts.counts(List.copyOf(all.keySet())).keySet());
        for (RobotPair pair : pairs) {
            ReportedRobot a = listed.get(pair.first());
            ReportedRobot b = listed.get(pair.second());
            WallLoss.Crossing crossing = walls.between(a.x(), a.y(), b.x(), b.y());
            counted.put(pair, (double) crossing.count());
            all.put(pair, crossing);
        }
        crossings = Map.copyOf(all);
        return counted;
    }
}
