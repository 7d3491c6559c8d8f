package org.usarsim.wss.hub.core;

import java.net.InetAddress;
import java.util.List;

/**
 * A registered robot: its name, the address its control connection came from, the ports it
 * accepts on, and that connection (to tell whose a departure is, and to close it on a kick).
 */
public record RegisteredRobot(String name, InetAddress address, List<Integer> ports, RobotSession session) {

    public RegisteredRobot {
        ports = List.copyOf(ports);
    }

    /**
     * The port a DNS asks for: 0 means the first registered; -1 when the robot does not accept on
     * it. A registered port outside 1..65535 (INIT accepts any integer, as the original) is never
     * dialled: -1 too, where the original would dial a truncated number.
     */
    int resolvePort(int asked) {
        int port = asked != 0 ? asked : ports.isEmpty() ? -1 : ports.get(0);
        return port >= 1 && port <= 65535 && ports.contains(port) ? port : -1;
    }
}
