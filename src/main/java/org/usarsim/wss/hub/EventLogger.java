package org.usarsim.wss.hub;

import java.util.List;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.protocol.Strengths;
import org.usarsim.wss.shaping.Bitrate;

/** Writes each event to the log as one line (data sent only at FINEST: it happens per chunk; in and out of range at FINE). */
final class EventLogger implements WssEventListener {

    private static final Logger LOG = Logger.getLogger("org.usarsim.wss.events");

    /** The limit on lines an operator causes: forces and releases come as fast as FORCEs do. */
    private final WarningLimiter limits;

    EventLogger(WarningLimiter limits) {
        this.limits = limits;
    }

    @Override
    public void robotRegistered(String robot, String address, List<Integer> ports) {
        LOG.info(() -> "registered " + robot + " from " + address + " accepting on " + ports);
    }

    @Override
    public void robotDeregistered(String robot) {
        LOG.info(() -> "deregistered " + robot);
    }

    @Override
    public void robotOutOfBattery(String robot) {
        LOG.info(() -> "out of battery: " + robot);
    }

    /** FINE: the hub's INFO line "pair A - B: broken" says the change already (Hub.recordState). */
    @Override
    public void connectionOutOfRange(String from, String to, double strength, double distance) {
        LOG.fine(() -> "out of range: " + from + " - " + to + " at " + Strengths.format(strength)
                + " dBm, " + Strengths.format(distance) + " m");
    }

    /** FINE: the hub's INFO line "pair A - B: up" says the change already. */
    @Override
    public void connectionInRange(String from, String to) {
        LOG.fine(() -> "in range: " + from + " - " + to);
    }

    @Override
    public void connectionEstablished(String from, String to, int targetPort) {
        LOG.info(() -> "connection established " + from + " -> " + to + ":" + targetPort);
    }

    @Override
    public void connectionTerminated(String from, String to, int targetPort) {
        LOG.info(() -> "connection terminated " + from + " -> " + to + ":" + targetPort);
    }

    @Override
    public void pairForced(String first, String second, boolean up) {
        limits.info(LOG, "forced pairs", "forced " + first + " - " + second + (up ? " up" : " down"));
    }

    /** At FINE: a robot near a step of the rate table changes rate at many polls (the event log has every RATE). */
    @Override
    public void rateChanged(String from, String to, long bitsPerSecond) {
        LOG.fine(() -> "rate " + from + " -> " + to + ": " + Bitrate.format(bitsPerSecond));
    }

    @Override
    public void pairReleased(String first, String second) {
        limits.info(LOG, "released pairs", "released " + first + " - " + second + " to the model");
    }

    @Override
    public void dataSent(String from, String to, int bytes) {
        if (LOG.isLoggable(Level.FINEST)) { // per chunk: not even a lambda unless it is logged
            LOG.finest(bytes + " bytes " + from + " -> " + to);
        }
    }
}
