package org.usarsim.wss.model;

import java.util.List;

/**
 * What happens in the server, as it happens. Every method has an empty default, so a listener
 * overrides only what it needs. Called on the server's threads: return quickly.
 */
public interface WssEventListener {

    default void robotRegistered(String robot, String address, List<Integer> ports) {
    }

    default void robotDeregistered(String robot) {
    }

    default void robotOutOfBattery(String robot) {
    }

    default void connectionOutOfRange(String from, String to, double strength, double distance) {
    }

    default void connectionInRange(String from, String to) {
    }

    default void connectionEstablished(String from, String to, int targetPort) {
    }

    default void connectionTerminated(String from, String to, int targetPort) {
    }

    default void dataSent(String from, String to, int bytes) {
    }

    /**
     * The datagrams of the fixed UDP port {@code fixedPort} (its number on the WSS) from {@code from}
     * to {@code to} since its last such call (at most one a second, none for a second with nothing):
     * sent (and their bytes), dropped because the pair was broken, dropped because its shaped queue
     * was full, lost to the signal (docs/fixed-ports.md). Each fixed port says its own: two fixed UDP
     * ports of one pair make two calls, each with its port's datagrams only.
     */
    default void udpCounted(String from, String to, int fixedPort, long datagrams, long bytes, long droppedBroken, long droppedQueue,
            long lost) {
    }

    /** A DNS gave connections from {@code from} to {@code to}'s {@code targetPort} their own WSS port. */
    default void portAllocated(String from, String to, int targetPort, int wssPort, boolean listening) {
    }

    /** A WSS port started or stopped listening (a robot came or went, a pair broke or resumed). */
    default void portListening(String from, String to, int targetPort, int wssPort, boolean listening) {
    }

    /** A WSS port was given back to the OS (its robot was kicked out); the same DNS would get a new one. */
    default void portForgotten(String from, String to, int targetPort, int wssPort) {
    }

    /** With links shaped: the rate from one robot to another is now this many bit/s (first set, or changed). */
    default void rateChanged(String from, String to, long bitsPerSecond) {
    }

    /**
     * An operator forced the pair (names in ascending order) up or down: its state no longer
     * follows the model until {@link #pairReleased}.
     */
    default void pairForced(String first, String second, boolean up) {
    }

    /**
     * An operator pinned the shape of a pair forced up (names in ascending order; {@code FORCE ...
     * {Rate r} {Delay d} {Jitter j}}, docs/shaping.md), said after its {@link #pairForced}: its rate in
     * bit/s (0: not pinned), delay and jitter in ms (-1: not pinned), both ways, until released or forced again.
     */
    default void pairPinned(String first, String second, long bitsPerSecond, int delayMs, int jitterMs) {
    }

    /** An operator gave the forced pair (names in ascending order) back to the model. */
    default void pairReleased(String first, String second) {
    }

    /**
     * The replay was moved (docs/replay.md): an operator jumped, changed the speed, played or
     * paused it (the window's time bar, {@code REPLAY}); where it is now (seconds from the
     * recording's start), how fast, and whether it plays. Only for a move that changed something.
     */
    default void replayMoved(double timeSeconds, double speed, boolean playing) {
    }

    /**
     * A simulator model polled the simulator: what it learned and decided (docs/replay.md; the
     * recording writes it). Sent after the poll's kicks, before its breaks and resumes are applied.
     */
    default void polled(ModelPoll poll) {
    }

    /**
     * A robot is cut off from the base ({@code wss.route.base}, docs/routes.md): no route of
     * robots that are up now leads from it to the base. Once per change, not per poll.
     */
    default void cutOff(String robot) {
    }

    /**
     * A robot has a route to the base (again, or another one: other hops, or a rate that moved by
     * 10 % or more; docs/routes.md): its hops, its path ({@code A,R1,BASE}) and with links shaped
     * the rate one stream could have over it (bit/s; 0 unshaped). Once per change, not per poll.
     */
    default void routedToBase(String robot, int hops, String path, long bitsPerSecond) {
    }
}
