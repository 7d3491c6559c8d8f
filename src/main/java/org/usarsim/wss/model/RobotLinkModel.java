package org.usarsim.wss.model;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/** What the server lets a propagation model do to robots and their links. Thread-safe. */
public interface RobotLinkModel {

    /**
     * Stops every WSS port of the pair (both directions, every target port) from listening and
     * closes every established connection between them. Port numbers are kept.
     *
     * @return true when something changed
     */
    boolean breakConnectionsForPair(String robotA, String robotB);

    /**
     * Lets the pair's WSS ports listen again, on the same port numbers.
     *
     * @return true when something changed
     */
    boolean resumeConnectionsForPair(String robotA, String robotB);

    /**
     * Breaks the pairs that are out of range and resumes those in range, as
     * {@link #breakConnectionsForPair} and {@link #resumeConnectionsForPair} do, in one go: a robot
     * that drives out of range of a hundred others stops its two hundred ports together. The
     * server applies it as one change; this default, one pair after the other.
     *
     * @param inRange each pair and whether it is in range now, in the order to apply them
     * @return the pairs for which something changed, in that order
     */
    default Set<RobotPair> applyLinkStates(Map<RobotPair, Boolean> inRange) {
        Set<RobotPair> changed = new LinkedHashSet<>();
        inRange.forEach((pair, live) -> {
            boolean did = live ? resumeConnectionsForPair(pair.first(), pair.second())
                    : breakConnectionsForPair(pair.first(), pair.second());
            if (did) {
                changed.add(pair);
            }
        });
        return changed;
    }

    /** Closes all the robot's data connections, forgets its WSS ports, deregisters it and closes its control connection. */
    void kickOutRobot(String robot);

    /** The names of the registered robots, sorted. */
    List<String> getListOfRegisteredRobots();
}
