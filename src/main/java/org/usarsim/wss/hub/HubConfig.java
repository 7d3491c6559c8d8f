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
 */
public record HubConfig(InetAddress bindAddress, int controlPort, int chunkSize, int socketBuffer,
        boolean matchSourceAddress) {
}
