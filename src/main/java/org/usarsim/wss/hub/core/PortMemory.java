package org.usarsim.wss.hub.core;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * How long the WSS ports of a robot that left keep their numbers ({@code wss.portMemory}): when
 * each robot left, and whether that is long enough ago. A pure rule: the time comes in with each
 * call; the timer that asks again once the time may have passed is the hub's (the core says when,
 * {@link Changes#forgetLater}). It keeps the robots in the order they left, so that when
 * descriptors run short the ports of the one gone longest are given back first, whatever the
 * setting (for ever too).
 */
final class PortMemory {

    /** Never forget. */
    static final int FOREVER = -1;

    private final long memoryNs;
    private final boolean forever;
    /** When each robot that left and still has ports left, the one gone longest first. */
    private final Map<String, Long> goneSince = new LinkedHashMap<>();

    PortMemory(int seconds) {
        this.forever = seconds == FOREVER;
        this.memoryNs = TimeUnit.SECONDS.toNanos(Math.max(0, seconds));
    }

    /** How long after a departure the ports are forgotten; meaningless when {@link #never()}. */
    long memoryNs() {
        return memoryNs;
    }

    /** Whether ports are never forgotten (wss.portMemory = -1, as the original). */
    boolean never() {
        return forever;
    }

    /** A robot left. @return true when its ports are to be forgotten now (wss.portMemory = 0) */
    boolean left(String robot, long nowNs) {
        goneSince.remove(robot); // to the end: it is the one gone least long now
        goneSince.put(robot, nowNs);
        return !forever && memoryNs == 0;
    }

    /** The robots that left and still have ports, the one gone longest first. */
    List<String> longestGoneFirst() {
        return List.copyOf(goneSince.keySet());
    }

    /** A robot registered again, or its ports were all forgotten: nothing to remember about its departure. */
    void clear(String robot) {
        goneSince.remove(robot);
    }

    /** Whether the robot has been gone at least as long as ports are remembered. */
    boolean expired(String robot, long nowNs) {
        Long since = goneSince.get(robot);
        return !forever && since != null && nowNs - since >= memoryNs;
    }

    /** Whole seconds since the robot left (0 when it has not). */
    long goneSeconds(String robot, long nowNs) {
        Long since = goneSince.get(robot);
        return since == null ? 0 : TimeUnit.NANOSECONDS.toSeconds(nowNs - since);
    }
}
