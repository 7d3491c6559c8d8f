package org.usarsim.wss.hub;

import java.util.List;
import org.usarsim.wss.hub.core.DeclaredRobot;
import org.usarsim.wss.hub.core.FixedPort;

/**
 * The robots declared instead of registering and the fixed ports between them (docs/fixed-ports.md):
 * present from Start to Stop.
 *
 * @param robots         the declared robots ({@code wss.robot.NAME = ADDRESS}), in the order of their names
 * @param ports          the fixed ports ({@code wss.fixed}), in the order written
 * @param udpIdleSeconds how long a UDP session (one sender's socket of the WSS) lives without a datagram either way
 */
public record FixedSetup(List<DeclaredRobot> robots, List<FixedPort> ports, int udpIdleSeconds) {

    /** wss.udpIdleSeconds' default. */
    public static final int DEFAULT_UDP_IDLE_SECONDS = 60;

    /** No robot declared, no fixed port. */
    public static final FixedSetup NONE = new FixedSetup(List.of(), List.of(), DEFAULT_UDP_IDLE_SECONDS);

    public FixedSetup {
        robots = List.copyOf(robots);
        ports = List.copyOf(ports);
    }

    /** The ports a declared robot accepts on: the target ports of the fixed ports toward it, each once. */
    public List<Integer> portsOf(String robot) {
        return ports.stream().filter(port -> port.key().to().equals(robot)).map(port -> port.key().targetPort()).distinct().toList();
    }
}
