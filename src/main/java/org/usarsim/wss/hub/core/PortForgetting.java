package org.usarsim.wss.hub.core;

import java.util.function.Predicate;
import java.util.logging.Level;

/**
 * When the WSS ports of robots that left are forgotten, and how a port is given back: after
 * wss.portMemory ({@link PortMemory}), at once when descriptors run short (the robot gone longest
 * first), or with its last connection. The one place a port's number is given back
 * ({@link #giveBack}) and a port forgotten ({@link #forget}). Part of the {@link HubCore}, under its lock.
 */
final class PortForgetting {

    private final Ports ports;
    private final PortMemory memory;
    private final Pairs pairs;
    /** Whether a robot is registered now. */
    private final Predicate<String> registered;

    PortForgetting(Ports ports, PortMemory memory, Pairs pairs, Predicate<String> registered) {
        this.ports = ports;
        this.memory = memory;
        this.pairs = pairs;
        this.registered = registered;
    }

    /** The port's number is given back: it listens no more and its socket is closed. */
    static void giveBack(WssPort port, Changes out) {
        port.stopListening();
        out.port(Changes.PortWork.RELEASE, port);
    }

    /** The port is given back and forgotten: a DNS of its key allocates a new one. */
    void forget(WssPort port, Changes out) {
        giveBack(port, out);
        ports.remove(port);
        out.add(new HubEvent.PortForgotten(port.key, port.number));
    }

    /** A robot came: its ports are remembered for good again. */
    void arrived(String name) {
        memory.clear(name);
    }

    /** A robot left: its ports are forgotten now (wss.portMemory = 0) or later. */
    void left(String name, long nowNs, Changes out) {
        if (memory.left(name, nowNs)) {
            forgetPortsOf(name, nowNs, out);
        } else if (!memory.never()) {
            out.forgetLater(name, memory.memoryNs());
        }
    }

    /** A robot was kicked out (its ports forgotten already): what it held is remembered from now as if it left. */
    void kicked(String name, long nowNs, Changes out) {
        memory.clear(name);
        left(name, nowNs, out);
    }

    /** The hub's timer, wss.portMemory after a robot left: forget its ports unless it came back. */
    void forgetIfGone(String name, long nowNs, Changes out) {
        if (!registered.test(name) && memory.expired(name, nowNs)) {
            forgetPortsOf(name, nowNs, out);
        }
    }

    /** A port's last connection ended: a port kept only for it is forgotten with it. */
    void linkEnded(WssPort port, long nowNs, Changes out) {
        for (String robot : new String[] {port.key.from(), port.key.to()}) {
            if (!port.hasLinks() && !registered.test(robot) && memory.expired(robot, nowNs)) {
                forgetPortsOf(robot, nowNs, out);
            }
        }
    }

    /**
     * Gives back the numbers of a gone robot's WSS ports, as source and as target, but those with
     * open connections, which are forgotten when their last connection closes.
     */
    private int forgetPortsOf(String name, long nowNs, Changes out) {
        int forgotten = 0;
        boolean kept = false;
        for (WssPort port : ports.of(name)) {
            if (!port.hasLinks()) {
                forget(port, out);
                forgotten++;
            } else {
                kept = true;
            }
        }
        if (forgotten > 0) {
            out.add(new HubEvent.Said(Level.INFO, "forgotten WSS ports", "forgot " + forgotten + " WSS port" + (forgotten == 1 ? "" : "s") + " of " + name
                    + ", gone for " + memory.goneSeconds(name, nowNs) + " s"));
        }
        if (!kept) {
            memory.clear(name);
        }
        pairs.forget(name, pair -> ports.between(pair).isEmpty());
        return forgotten;
    }

    /**
     * Descriptors ran short: the remembered ports of robots that left are given back, the robot
     * gone longest first, a whole robot at a time, until at least {@code atLeast} were (or none is
     * left to give), whatever wss.portMemory says. A robot that is here never loses a port so.
     *
     * @return how many ports were given back
     */
    int giveBackRemembered(int atLeast, long nowNs, Changes out) {
        int given = 0;
        int of = 0;
        for (String name : memory.longestGoneFirst()) {
            if (given >= atLeast) {
                break;
            }
            if (!registered.test(name)) {
                int forgotten = forgetPortsOf(name, nowNs, out);
                given += forgotten;
                of += forgotten > 0 ? 1 : 0;
            }
        }
        if (given > 0) {
            out.add(new HubEvent.Said(Level.INFO, "ports given back", "descriptors ran short: gave back " + given + " remembered WSS port"
                    + (given == 1 ? "" : "s") + " of " + of + " robot" + (of == 1 ? "" : "s") + " that left, the longest gone first"));
        }
        return given;
    }
}
