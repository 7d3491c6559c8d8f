package org.usarsim.wss.hub;

import org.usarsim.wss.model.RobotPair;

/** What a WSS port is for: connections from one robot to one port of another. */
record PortKey(String from, String to, int targetPort) {

    /** The two robots, in no particular order: what a break or a resume names. */
    RobotPair pair() {
        return RobotPair.of(from, to);
    }

    @Override
    public String toString() {
        return from + " -> " + to + ":" + targetPort;
    }
}
