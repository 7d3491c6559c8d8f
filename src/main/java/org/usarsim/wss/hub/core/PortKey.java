package org.usarsim.wss.hub.core;

import org.usarsim.wss.model.RobotPair;

/** What a WSS port is for: connections from one robot to one port of another. */
public record PortKey(String from, String to, int targetPort) {
    /**
     * Not the record's {@code 31 * h(a) + h(b)}: a name's own hash is a sum of powers of 31, so
     * that sum makes R12 -> R34 and R13 -> R24 alike; the 9,900 pairs of a 100-robot mesh had
     * 2,788 hashes between them, and the hub's maps of pairs and ports searched trees of them.
     */
    @Override
    public int hashCode() {
        return (from.hashCode() * 0x9E3779B9 + to.hashCode()) * 0x9E3779B9 + targetPort;
    }

    /** The two robots, in no particular order: what a break or a resume names. */
    public RobotPair pair() {
        return RobotPair.of(from, to);
    }

    @Override
    public String toString() {
        return from + " -> " + to + ":" + targetPort;
    }
}
