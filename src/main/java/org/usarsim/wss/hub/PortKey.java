package org.usarsim.wss.hub;

import org.usarsim.wss.model.RobotPair;

/** What a WSS port is for: connections from one robot to one port of another. */
record PortKey(String from, String to, int targetPort) {

    boolean involves(String robot) {
        return from.equals(robot) || to.equals(robot);
    }

    boolean isBetween(RobotPair pair) {
        return pair.equals(RobotPair.of(from, to));
    }

    @Override
    public String toString() {
        return from + " -> " + to + ":" + targetPort;
    }
}
