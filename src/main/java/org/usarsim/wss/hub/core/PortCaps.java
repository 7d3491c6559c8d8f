package org.usarsim.wss.hub.core;

import java.net.InetAddress;
import java.util.Collection;

/**
 * The caps on the WSS ports one client may hold as source, so that it cannot take every
 * descriptor: per robot (wss.maxPortsPerRobot) and for the robots registered from one address
 * together (wss.maxPortsPerAddress). Rules of the DNS, under the core's lock.
 */
final class PortCaps {

    private final int maxPortsPerRobot;
    private final int maxPortsPerAddress;

    PortCaps(int maxPortsPerRobot, int maxPortsPerAddress) {
        this.maxPortsPerRobot = maxPortsPerRobot;
        this.maxPortsPerAddress = maxPortsPerAddress;
    }

    /**
     * Whether a new port for {@code key} goes beyond a cap; if so, the WARNING its client caused
     * is in {@code out}.
     *
     * @param robots the robots registered now
     */
    boolean refuse(PortKey key, Collection<RegisteredRobot> robots, Ports ports, InetAddress address, Changes out) {
        String from = key.from();
        int held = ports.fromCount(from);
        if (held >= maxPortsPerRobot) {
            out.add(new HubEvent.Warned("DNS beyond the port limit", address, from + " holds " + held
                    + " WSS ports as source, the most wss.maxPortsPerRobot allows; no new one for " + key));
            return true;
        }
        long heldFromAddress = heldFrom(address, robots, ports);
        if (heldFromAddress >= maxPortsPerAddress) {
            out.add(new HubEvent.Warned("DNS beyond the address limit", address, "the robots registered from "
                    + address.getHostAddress() + " hold " + heldFromAddress
                    + " WSS ports as source, the most wss.maxPortsPerAddress allows; no new one for " + key));
            return true;
        }
        return false;
    }

    /**
     * The WSS ports held as source by the robots registered from the address now. Ports of robots
     * that left are not counted: they give their descriptors back when descriptors run short
     * ({@link PortForgetting#giveBackRemembered}).
     */
    private static long heldFrom(InetAddress address, Collection<RegisteredRobot> robots, Ports ports) {
        long held = 0;
        for (RegisteredRobot robot : robots) {
            if (robot.address().equals(address)) {
                held += ports.fromCount(robot.name());
            }
        }
        return held;
    }
}
