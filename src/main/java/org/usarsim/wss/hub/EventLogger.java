package org.usarsim.wss.hub;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.protocol.Strengths;
import org.usarsim.wss.shaping.Bitrate;

/**
 * Writes each event to the log as one line (data sent only at FINEST: it happens per chunk; in and
 * out of range at FINE). Every INFO line is limited per kind, and blamed on the address of the
 * robot it is about (the source's, for a connection), as the warnings are: a client registering
 * and leaving in a loop cannot fill the disk (issue 27, docs/reliability.md).
 */
final class EventLogger implements WssEventListener {

    private static final Logger LOG = Logger.getLogger("org.usarsim.wss.events");

    /** The limit on lines an operator causes: forces and releases come as fast as FORCEs do. */
    private final WarningLimiter limits;

    /** The address of each registered robot, the one its lines are blamed on; as many as robots registered. */
    private final Map<String, InetAddress> addresses = new ConcurrentHashMap<>();

    EventLogger(WarningLimiter limits) {
        this.limits = limits;
    }

    @Override
    public void robotRegistered(String robot, String address, List<Integer> ports) {
        InetAddress from = literal(address);
        if (from != null) {
            addresses.put(robot, from);
        }
        say("registered robots", robot, "registered " + robot + " from " + address + " accepting on " + ports);
    }

    @Override
    public void robotDeregistered(String robot) {
        say("deregistered robots", robot, "deregistered " + robot);
        addresses.remove(robot);
    }

    @Override
    public void robotOutOfBattery(String robot) {
        say("robots out of battery", robot, "out of battery: " + robot);
    }

    private void say(String kind, String robot, String line) {
        if (LOG.isLoggable(Level.INFO)) {
            limits.say(LOG, Level.INFO, kind, addresses.get(robot), line);
        }
    }

    /** The address the hub gave as text (always a literal: nothing is looked up), or null. */
    private static InetAddress literal(String address) {
        try {
            boolean literal = address != null && (address.indexOf('.') >= 0 || address.indexOf(':') >= 0)
                    && address.chars().allMatch(c -> Character.digit(c, 16) >= 0 || c == '.' || c == ':' || c == '%');
            return literal ? InetAddress.getByName(address) : null;
        } catch (UnknownHostException e) {
            return null;
        }
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
        say("connections established", from, "connection established " + from + " -> " + to + ":" + targetPort);
    }

    @Override
    public void connectionTerminated(String from, String to, int targetPort) {
        say("connections terminated", from, "connection terminated " + from + " -> " + to + ":" + targetPort);
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
    public void cutOff(String robot) {
        limits.info(LOG, "routes to the base", robot + " is cut off from the base");
    }

    @Override
    public void routedToBase(String robot, int hops, String path, long bitsPerSecond) {
        limits.info(LOG, "routes to the base", "route " + robot + " to the base: " + path + ", " + hops + (hops == 1 ? " hop" : " hops")
                + (bitsPerSecond > 0 ? ", " + Bitrate.format(bitsPerSecond) : ""));
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
