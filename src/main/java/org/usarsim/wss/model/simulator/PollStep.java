package org.usarsim.wss.model.simulator;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.model.RobotPair;

/**
 * What a poll decides, from what it learned: which robots are kicked and why, which pairs are
 * decided, and each pair's link state. Pure: no socket, no clock, no hub; the model applies the
 * result through {@code RobotLinkModel}. Who is kicked and which pairs are decided
 * ({@link #kicks}, {@link #present}, {@link #pairs}) are public: the replay of a recording
 * ({@code replay.ReplayPropagationModel}) applies its recorded polls by the same rules.
 */
public final class PollStep {

    /** A robot's strength to another, given the obstacles between them (NaN: not counted). */
    @FunctionalInterface
    interface Strength {
        double between(ReportedRobot a, ReportedRobot b, double obstacles);
    }

    /** A registered robot to kick: one the simulator does not list, or one whose battery is empty. */
    public record Kick(String robot, boolean batteryEmpty) {
        /** Why, in words, when {@code lister} (the simulator, the recording) lists the robots. */
        public String reason(String lister) {
            return batteryEmpty ? "its battery is empty" : "the " + lister + " does not list it";
        }
    }

    /** A pair's decided state, with the strength and distance it was decided on. */
    record Link(RobotPair pair, boolean live, double strength, double distance) {
    }

    /** The links to set, in pair order, and the snapshot to publish before setting them. */
    record Decision(List<Link> links, PollSnapshot snapshot) {
    }

    private PollStep() {
    }

    /** The registered robots to kick, in their order: absent from {@code listed} (when {@code kickAbsent}) or out of battery. */
    public static List<Kick> kicks(List<String> registered, Map<String, ReportedRobot> listed, boolean kickAbsent) {
        List<Kick> kicks = new ArrayList<>();
        for (String robot : registered) {
            ReportedRobot state = listed.get(robot);
            if (state == null && kickAbsent) {
                kicks.add(new Kick(robot, false));
            } else if (state != null && state.batteryEmpty()) {
                kicks.add(new Kick(robot, true));
            }
        }
        return kicks;
    }

    /** The registered robots the simulator lists with battery left: the ones whose links are decided. */
    public static List<String> present(List<String> registered, Map<String, ReportedRobot> listed) {
        return registered.stream().filter(robot -> listed.containsKey(robot) && !listed.get(robot).batteryEmpty()).toList();
    }

    /** Every pair of the present robots, each once, in their order. */
    public static List<RobotPair> pairs(List<String> present) {
        List<RobotPair> pairs = new ArrayList<>();
        for (int i = 0; i < present.size(); i++) {
            for (int j = i + 1; j < present.size(); j++) {
                pairs.add(RobotPair.of(present.get(i), present.get(j)));
            }
        }
        return pairs;
    }

    /**
     * Decides every pair of the present robots at {@code now} from the previous states (left as
     * they were): the states of pairs with a robot no longer present are forgotten.
     */
    static Decision decide(List<String> present, Map<String, ReportedRobot> listed, Map<RobotPair, Double> obstacles,
            long now, LinkStates previous, Strength strength) {
        LinkStates states = previous.copy();
        states.retainOnly(new HashSet<>(present));
        List<Link> links = new ArrayList<>();
        for (RobotPair pair : pairs(present)) {
            ReportedRobot a = listed.get(pair.first());
            ReportedRobot b = listed.get(pair.second());
            double value = strength.between(a, b, obstacles.getOrDefault(pair, Double.NaN));
            links.add(new Link(pair, states.decide(pair, value, now), value, a.distanceTo(b)));
        }
        return new Decision(links, new PollSnapshot(listed, obstacles, states, now));
    }
}
