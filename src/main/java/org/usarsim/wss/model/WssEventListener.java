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
}
