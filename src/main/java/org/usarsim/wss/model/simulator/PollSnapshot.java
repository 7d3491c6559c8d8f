package org.usarsim.wss.model.simulator;

import java.util.Map;
import org.usarsim.wss.model.RobotPair;

/**
 * What one poll learned and decided, published whole: the positions, the obstacle counts asked
 * with them, the link states decided from both, and when. Never changed once made, so a GETSS or
 * an accept reads one poll's positions with that same poll's counts.
 */
record PollSnapshot(Map<String, ReportedRobot> positions, Map<RobotPair, Double> obstacles, LinkStates links, long nanos) {

    PollSnapshot {
        positions = Map.copyOf(positions);
        obstacles = Map.copyOf(obstacles);
    }

    /** Before the first poll of a run: nothing known. */
    static PollSnapshot empty(LinkStates links, long nanos) {
        return new PollSnapshot(Map.of(), Map.of(), links, nanos);
    }

    /** The pair's obstacle count; NaN when it was not counted. */
    double obstacles(RobotPair pair) {
        return obstacles.getOrDefault(pair, Double.NaN);
    }
}
