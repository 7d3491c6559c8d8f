package org.usarsim.wss.model.simulator;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.BooleanSupplier;
import java.util.logging.Logger;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.model.WssEventListener;

/**
 * A model that decides its links poll by poll from a list of robots and where they are: the
 * simulator models ({@link SimulatorModel}, which ask a simulator) and the replay of a recording
 * ({@code replay.ReplayPropagationModel}, which reads its polls). Here, once for all of them: the
 * values given before a start, the server to act on and the listener, and how a poll is applied
 * through {@link RobotLinkModel} ({@link #applyPoll}).
 */
public abstract class PollingModel implements PropagationModel {

    /** The model's logger, named for its class. */
    protected final Logger log = Logger.getLogger(getClass().getName());

    /** The values given by {@link #configure}, over the declared defaults: checked at each start. */
    private volatile Map<String, String> given = Map.of();
    private volatile RobotLinkModel linkModel;
    private volatile WssEventListener listener = new WssEventListener() {
    };

    /** Takes the values over those given before; they are checked, by their settings' rules, at the next start. */
    @Override
    public final void configure(ModelSettings settings) {
        Map<String, String> values = new HashMap<>(given);
        values.putAll(settings.asMap());
        given = Map.copyOf(values);
    }

    @Override
    public final void setRobotLinkModel(RobotLinkModel linkModel) {
        this.linkModel = linkModel;
    }

    @Override
    public final void setEventListener(WssEventListener listener) {
        this.listener = listener;
    }

    /** The values given so far (unchecked), by key. */
    protected final Map<String, String> given() {
        return given;
    }

    /** The server to act on: what a start needs first. */
    protected final RobotLinkModel server() throws ModelStartException {
        RobotLinkModel server = linkModel;
        if (server == null) {
            throw new ModelStartException("no server to act on (setRobotLinkModel was not called)");
        }
        return server;
    }

    /** Where the model reports what it decides. */
    protected final WssEventListener listener() {
        return listener;
    }

    /**
     * One poll as it came: the registered robots when it was taken, the robots it lists (by name,
     * in its order), whether a registered robot it does not list is kicked, who lists them (for
     * the log: "the simulator", "the recording") and when (appended to the kick's log line, empty
     * or " at 01:20"), the walls known by then, and whether the run stopped meanwhile.
     */
    public record Poll(List<String> registered, Map<String, ReportedRobot> listed, boolean kickAbsent, String lister,
            String when, List<Wall> walls, BooleanSupplier stopped) {
    }

    /** Decides the poll's pairs once its kicks are done. */
    @FunctionalInterface
    public interface Decider {

        /**
         * The state of every pair of the present robots ({@link PollStep#pairs}), published for
         * GETSS before it returns; null when the run stopped meanwhile.
         */
        List<ModelPoll.Pair> decide(List<String> present) throws IOException;
    }

    /**
     * Applies a poll: kicks the registered robots it does not list (when it kicks those) or lists
     * with an empty battery, has {@code decider} decide every pair of the present robots, announces
     * the poll ({@code polled}), then breaks and resumes the pairs in one go and tells each change.
     * Stops short, acting on nothing more, when the poll's run stopped.
     *
     * <p>The pairs are decided for the robots of {@link Poll#registered()} the poll kept, not for
     * the server's list read again: a robot that registers while the poll is applied was not
     * checked against it, and the next poll (the replay: its next look, at once) kicks it or
     * decides its pairs. Were it counted as applied, a replay holding still at its end would never
     * look at it again, and a robot the recording never had would stay.
     *
     * @return the registered robots the poll was applied to (those of {@link Poll#registered()} it
     *         did not kick); null when the run stopped
     */
    protected final List<String> applyPoll(Poll poll, Decider decider) throws IOException {
        RobotLinkModel server = linkModel;
        List<ModelPoll.Kick> kicks = new ArrayList<>();
        List<String> kept = new ArrayList<>(poll.registered());
        for (PollStep.Kick kick : PollStep.kicks(poll.registered(), poll.listed(), poll.kickAbsent())) {
            if (poll.stopped().getAsBoolean()) {
                return null;
            }
            log.info("kicking " + kick.robot() + ": " + kick.reason(poll.lister()) + poll.when());
            if (kick.batteryEmpty()) {
                listener.robotOutOfBattery(kick.robot());
            }
            server.kickOutRobot(kick.robot());
            kicks.add(new ModelPoll.Kick(kick.robot(), kick.batteryEmpty()));
            kept.remove(kick.robot());
        }
        List<ModelPoll.Pair> pairs = decider.decide(PollStep.present(kept, poll.listed()));
        if (pairs == null || poll.stopped().getAsBoolean()) {
            return null;
        }
        listener.polled(new ModelPoll(robots(poll.listed()), kicks, pairs, poll.walls()));
        // Every pair's state in one go: a robot that drove out of range of many stops all their ports together.
        Map<RobotPair, Boolean> inRange = new LinkedHashMap<>();
        pairs.forEach(pair -> inRange.put(RobotPair.of(pair.first(), pair.second()), pair.live()));
        Set<RobotPair> changed = server.applyLinkStates(inRange);
        for (ModelPoll.Pair pair : pairs) {
            RobotPair both = RobotPair.of(pair.first(), pair.second());
            if (!changed.contains(both)) {
                continue;
            }
            if (pair.live()) {
                log.fine(both + " in range: " + pair.strength() + " dBm");
                listener.connectionInRange(pair.first(), pair.second());
            } else {
                double distance = poll.listed().get(pair.first()).distanceTo(poll.listed().get(pair.second()));
                log.fine(both + " out of range: " + pair.strength() + " dBm at " + metres(distance));
                listener.connectionOutOfRange(pair.first(), pair.second(), pair.strength(), distance);
            }
        }
        return List.copyOf(kept);
    }

    private static List<ModelPoll.Robot> robots(Map<String, ReportedRobot> listed) {
        List<ModelPoll.Robot> robots = new ArrayList<>(listed.size());
        for (ReportedRobot robot : listed.values()) {
            robots.add(new ModelPoll.Robot(robot.name(), new Position(robot.x(), robot.y(), robot.z()), robot.batteryEmpty()));
        }
        return robots;
    }

    /** Metres with two decimals, as the log says a distance. */
    static String metres(double metres) {
        return String.format(java.util.Locale.ROOT, "%.2f m", metres);
    }
}
