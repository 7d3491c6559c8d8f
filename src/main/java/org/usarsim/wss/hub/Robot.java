package org.usarsim.wss.hub;

import java.net.InetAddress;
import java.util.List;

/** A registered robot: its name, the address its control connection came from, the ports it accepts on. */
record Robot(String name, InetAddress address, List<Integer> ports, ControlSession session) {

    Robot {
        ports = List.copyOf(ports);
    }

    /** The port a DNS asks for: 0 means the first registered; -1 when the robot does not accept on it. */
    int resolvePort(int asked) {
        if (asked == 0) {
            return ports.isEmpty() ? -1 : ports.get(0);
        }
        return ports.contains(asked) ? asked : -1;
    }
}
