package org.usarsim.wss.hub;

import java.net.InetAddress;

/**
 * How the hub runs.
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
 * @param deadPeerSeconds    within how many seconds TCP keepalive finds a peer that vanished,
 *                           on control connections and links; 0 leaves keepalive to the OS
 */
public record HubConfig(InetAddress bindAddress, int controlPort, int chunkSize, int socketBuffer,
        boolean matchSourceAddress, int portMemorySeconds, int maxPortsPerRobot, int deadPeerSeconds) {

    /** The same, listening for robots on another control port (the window's "Listen on port:"). */
    public HubConfig withControlPort(int port) {
        return new HubConfig(bindAddress, port, chunkSize, socketBuffer, matchSourceAddress, portMemorySeconds,
                maxPortsPerRobot, deadPeerSeconds);
    }
}
