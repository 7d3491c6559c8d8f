package org.usarsim.wss.hub;

/** What a WSS port is for: connections from one robot to one port of another. */
record PortKey(String from, String to, int targetPort) {

    boolean involves(String robot) {
        return from.equals(robot) || to.equals(robot);
    }

    boolean isBetween(Pair pair) {
        return pair.equals(Pair.of(from, to));
    }

    @Override
    public String toString() {
        return from + " -> " + to + ":" + targetPort;
    }
}
