package org.usarsim.wss.hub.core;

import org.usarsim.wss.model.RobotPair;

/** The core's parts whose constructors are the core's own, for the tests of the socket classes (a {@code tcp.Link} alone). */
public final class CoreFixtures {

    private CoreFixtures() {
    }

    /** WSS port {@code number} from robot {@code from} to {@code to}'s {@code targetPort}. */
    public static WssPort port(String from, String to, int targetPort, int number) {
        return new WssPort(new PortKey(from, to, targetPort), number);
    }

    /** The counters of the pair {@code a}-{@code b}, up since {@code nowNs}. */
    public static PairStats stats(String a, String b, long nowNs) {
        return new PairStats(RobotPair.of(a, b), PairState.UP, true, nowNs);
    }

    /** A pair's condition one way, as the core keeps it. */
    public static LiveCondition condition(PairCondition initial) {
        return new LiveCondition(initial);
    }
}
