package org.usarsim.wss.model;

import java.util.List;

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

    /** Closes all the robot's data connections, forgets its WSS ports, deregisters it and closes its control connection. */
    void kickOutRobot(String robot);

    /** The names of the registered robots, sorted. */
    List<String> getListOfRegisteredRobots();
}
