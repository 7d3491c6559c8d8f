package org.usarsim.wss.hub;

import java.net.InetAddress;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * How the hub runs. Built one way: this canonical constructor, every component given (the
 * application's from ConfigFile), then the {@code with...} methods for what the window or a test
 * changes.
 *
 * @param bindAddress        the address the control port and every WSS port listen on
 *                           (the wildcard address: every interface)
 * @param controlPort        the control port; 0 lets the OS choose
 * @param chunkSize          the most bytes a link reads and writes at a time, each way
 * @param socketBuffer       the send and receive buffer size of both sockets of a link; 0 leaves it to the OS
 * @param matchSourceAddress accept a connection on a WSS port only from the source robot's control address
 * @param portMemorySeconds  how long the WSS ports of a robot that left keep their numbers:
 *                           0 forgets them as it leaves, -1 never
 * @param maxPortsPerRobot   the most WSS ports one robot may hold as source
 * @param maxPortsPerAddress the most WSS ports the robots registered from one address may hold as source, together
 * @param deadPeerSeconds    within how many seconds TCP keepalive finds a peer that vanished,
 *                           on control connections and links; 0 leaves keepalive to the OS
 * @param operators          the addresses whose control connections may use the operator command (FORCE)
 * @param forced             the pairs forced down or up from the start (wss.force.down, wss.force.up)
 * @param pins               the rates and delays pinned with the pairs forced up from the start
 * @param shaping            how links are shaped (wss.shaping and its keys, docs/shaping.md)
 * @param fixed              the declared robots and fixed ports (docs/fixed-ports.md)
 */
public record HubConfig(InetAddress bindAddress, int controlPort, int chunkSize, int socketBuffer,
        boolean matchSourceAddress, int portMemorySeconds, int maxPortsPerRobot, int maxPortsPerAddress, int deadPeerSeconds,
        Set<InetAddress> operators, Map<RobotPair, Force> forced, Map<RobotPair, RatePin> pins, ShapingConfig shaping, FixedSetup fixed) {

    /**
     * wss.maxPortsPerAddress's default: a full mesh of 100 robots simulated on one computer asks
     * for 9,900 WSS ports from its one address, and must fit; at one descriptor a port, 10,000 is
     * half of a 20,000-descriptor limit, so one client cannot take them all.
     */
    public static final int MAX_PORTS_PER_ADDRESS = 10_000;

    public HubConfig {
        operators = Set.copyOf(operators);
        forced = Collections.unmodifiableMap(new LinkedHashMap<>(forced)); // forced at the start in this order
        pins = Map.copyOf(pins);
        Objects.requireNonNull(shaping, "shaping");
        Objects.requireNonNull(fixed, "fixed");
    }

    /** The same, listening for robots on another control port (the window's "Listen on port:"). */
    public HubConfig withControlPort(int port) {
        return new HubConfig(bindAddress, port, chunkSize, socketBuffer, matchSourceAddress, portMemorySeconds,
                maxPortsPerRobot, maxPortsPerAddress, deadPeerSeconds, operators, forced, pins, shaping, fixed);
    }

    /** The same, with another cap on the WSS ports of the robots of one address. */
    public HubConfig withMaxPortsPerAddress(int ports) {
        return new HubConfig(bindAddress, controlPort, chunkSize, socketBuffer, matchSourceAddress, portMemorySeconds,
                maxPortsPerRobot, ports, deadPeerSeconds, operators, forced, pins, shaping, fixed);
    }

    /** The same, with links shaped so (and these rates pinned from the start). */
    public HubConfig withShaping(ShapingConfig shaping, Map<RobotPair, RatePin> pins) {
        return new HubConfig(bindAddress, controlPort, chunkSize, socketBuffer, matchSourceAddress, portMemorySeconds,
                maxPortsPerRobot, maxPortsPerAddress, deadPeerSeconds, operators, forced, pins, shaping, fixed);
    }

    /** The same, with these robots declared and these fixed ports. */
    public HubConfig withFixed(FixedSetup setup) {
        return new HubConfig(bindAddress, controlPort, chunkSize, socketBuffer, matchSourceAddress, portMemorySeconds,
                maxPortsPerRobot, maxPortsPerAddress, deadPeerSeconds, operators, forced, pins, shaping, setup);
    }
}
