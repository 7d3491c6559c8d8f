package org.usarsim.wss.hub.core;

import org.usarsim.wss.model.RobotPair;

/** What a WSS port is for: connections from one robot to one port of another. */
public record PortKey(String from, String to, int targetPort) {

    /** The two robots, in no particular order: what a break or a resume names. */
    public RobotPair pair() {
        return RobotPair.of(from, to);
    }

    @Override
    public String toString() {
        return from + " -> " + to + ":" + targetPort;
    }
}
