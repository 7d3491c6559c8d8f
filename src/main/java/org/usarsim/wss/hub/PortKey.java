package org.usarsim.wss.hub;

/** What a WSS port is for: connections from one robot to one port of another. */
record PortKey(String from, String to, int targetPort) {

    /** The two robots, in no particular order: what a break or a resume names. */
    Pair pair() {
        return Pair.of(from, to);
    }

    @Override
    public String toString() {
        return from + " -> " + to + ":" + targetPort;
    }
}
