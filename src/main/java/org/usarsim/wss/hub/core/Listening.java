package org.usarsim.wss.hub.core;

import java.util.Map;
import java.util.function.BooleanSupplier;

/**
 * When a WSS port listens (the rule of {@link #shouldListen}), and the step's changes when it starts
 * or stops: the port work and the event. A part of {@link HubCore}, single-threaded as it is.
 */
final class Listening {

    /** The robots registered now (none once the core closed). */
    private final Map<String, RegisteredRobot> robots;
    private final Pairs pairs;
    /** Whether the core has closed: nothing listens any more. */
    private final BooleanSupplier closed;

    Listening(Map<String, RegisteredRobot> robots, Pairs pairs, BooleanSupplier closed) {
        this.robots = robots;
        this.pairs = pairs;
        this.closed = closed;
    }

    /**
     * A port of a pair just forced or released follows the verdict at once: not talking, it stops
     * listening and its links close; talking, it listens again where both robots are registered.
     */
    void followVerdict(WssPort port, boolean talks, CloseReason reason, Changes out) {
        if (!talks) {
            stopListening(port, out);
            port.closeLinks(reason, out);
        } else {
            listenIfItShould(port, true, out);
        }
    }

    /**
     * A WSS port listens while both robots are registered, the target still accepts on the
     * target port, and the model neither broke nor forbids the pair, unless an operator forced
     * it ({@link ForcedPairs#allows}).
     */
    boolean shouldListen(PortKey key, boolean modelAllows) {
        RegisteredRobot target = robots.get(key.to());
        return !closed.getAsBoolean() && robots.containsKey(key.from()) && target != null && target.ports().contains(key.targetPort())
                && pairs.talks(key.pair(), modelAllows);
    }

    /** A port that does not listen and should now listens again. @return whether it does */
    boolean listenIfItShould(WssPort port, boolean modelAllows, Changes out) {
        if (port.listening() || !shouldListen(port.key, modelAllows)) {
            return false;
        }
        port.listen();
        out.port(Changes.PortWork.LISTEN, port);
        out.add(new HubEvent.PortListening(port.key, port.number, true));
        return true;
    }

    /** @return true when it was listening */
    boolean stopListening(WssPort port, Changes out) {
        if (!port.stopListening()) {
            return false;
        }
        out.port(Changes.PortWork.STOP, port);
        out.add(new HubEvent.PortListening(port.key, port.number, false));
        return true;
    }
}
