package org.usarsim.wss.model.obstacle;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.logging.Logger;
import org.usarsim.wss.model.DialogLayout;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.simulator.PollClock;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.model.simulator.SimulatorConnection;
import org.usarsim.wss.model.simulator.SimulatorModel;

/**
 * The original's realisation of the manual's RayTracing idea: the DistanceOnly strength minus a
 * fixed attenuation per obstacle between the two robots, S = Pd0 - 10 N log10(d / d0) - k A. The
 * obstacle count k comes from the simulator ({@code GETOBS}) and is cached per pair until either
 * robot moves more than the cache distance. Pessimistic: a pair with an unknown position or
 * count has NaN strength and may not connect. Registered robots absent from a non-empty position
 * list are kicked.
 */
public final class ObstaclePropagationModel extends SimulatorModel {

    private static final Logger LOG = Logger.getLogger(ObstaclePropagationModel.class.getName());

    private static final List<Setting> OBSTACLES = List.of(
            Setting.number("obstacle.attenuation", "Attenuation per obstacle", "6.325").from(0).unit("dB")
                    .help("The loss for each obstacle between two robots"),
            Setting.number("obstacle.cacheDistance", "Cache distance", "1.0").from(0).unit("m")
                    .help("How far a robot moves before the obstacles between it and the others are counted again"));

    /** Read at each start; volatile for the threads that ask for a strength. */
    private volatile double attenuation;
    /** The GETOBS cache: used by the poller only, made afresh at each start. */
    private ObstacleCounts counts;
    /** Whether the last batch of GETOBS went unanswered (used by the poller only). */
    private boolean getobsUnanswered;

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

    @Override
    protected void started(ModelSettings settings) {
        attenuation = settings.getDouble("obstacle.attenuation", 0);
        counts = new ObstacleCounts(settings.getDouble("obstacle.cacheDistance", 0));
        getobsUnanswered = false;
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
     * Asks the simulator, in one batch, for the counts of the pairs whose count is unknown or no
     * longer holds; an unanswered pair's count is unknown. A simulator that answers none of a
     * batch is reported once, and again once it answers.
     */
    @Override
    protected Map<RobotPair, Double> obstacleCounts(Map<String, ReportedRobot> listed, List<RobotPair> pairs,
            SimulatorConnection simulator) throws IOException {
        ObstacleCounts known = counts;
        Set<RobotPair> current = new HashSet<>(pairs);
        known.retain(current::contains);
        List<RobotPair> stale = pairs.stream().filter(pair -> known.stale(pair, listed)).toList();
        if (stale.isEmpty()) {
            return known.counts(pairs);
        }
        Map<RobotPair, Double> answers = simulator.obstacles(stale);
        for (RobotPair pair : stale) {
            known.put(pair, answers.getOrDefault(pair, Double.NaN), listed);
        }
        if (answers.isEmpty() && !getobsUnanswered) {
            LOG.warning("the simulator answers no GETOBS (" + stale.size() + " asked): pairs whose obstacle count is unknown"
                    + " cannot connect");
        } else if (!answers.isEmpty() && getobsUnanswered) {
            LOG.info("the simulator answers GETOBS again");
        }
        getobsUnanswered = answers.isEmpty();
        return known.counts(pairs);
    }
}
