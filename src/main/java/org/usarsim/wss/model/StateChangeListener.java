package org.usarsim.wss.model;

import java.util.List;

/**
 * A {@link WssEventListener} that only wants to know that the state changed, whatever the change:
 * every event of robots, pairs, connections, ports, rates, forces, the replay and routes calls
 * {@link #changed()}; the counts ({@link #dataSent}, {@link #udpCounted}) and the model's polls
 * ({@link #polled}) do not, being many and read in their own time. The window's view, the
 * monitor's publisher and the hub's routes are told this way; each overrides what it wants more of.
 */
public interface StateChangeListener extends WssEventListener {

    /** The state changed: called on the thread that delivers the event, so it must only take note. */
    void changed();

    @Override
    default void robotRegistered(String robot, String address, List<Integer> ports) {
        changed();
    }

    @Override
    default void robotDeregistered(String robot) {
        changed();
    }

    @Override
    default void robotOutOfBattery(String robot) {
        changed();
    }

    @Override
    default void connectionOutOfRange(String from, String to, double strength, double distance) {
        changed();
    }

    @Override
    default void connectionInRange(String from, String to) {
        changed();
    }

    @Override
    default void connectionEstablished(String from, String to, int targetPort) {
        changed();
    }

    @Override
    default void connectionTerminated(String from, String to, int targetPort) {
        changed();
    }

    @Override
    default void portAllocated(String from, String to, int targetPort, int wssPort, boolean listening) {
        changed();
    }

    @Override
    default void portListening(String from, String to, int targetPort, int wssPort, boolean listening) {
        changed();
    }

    @Override
    default void portForgotten(String from, String to, int targetPort, int wssPort) {
        changed();
    }

    @Override
    default void rateChanged(String from, String to, long bitsPerSecond) {
        changed();
    }

    @Override
    default void pairForced(String first, String second, boolean up) {
        changed();
    }

    @Override
    default void pairPinned(String first, String second, long bitsPerSecond, int delayMs, int jitterMs) {
        changed();
    }

    @Override
    default void pairReleased(String first, String second) {
        changed();
    }

    @Override
    default void replayMoved(double timeSeconds, double speed, boolean playing) {
        changed();
    }

    @Override
    default void cutOff(String robot) {
        changed();
    }

    @Override
    default void routedToBase(String robot, int hops, String path, long bitsPerSecond) {
        changed();
    }
}
