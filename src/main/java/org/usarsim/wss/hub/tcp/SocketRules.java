package org.usarsim.wss.hub.tcp;

import java.net.InetAddress;
import java.util.logging.Logger;

/**
 * What every socket class of the hub follows, on the control side ({@link ControlHub}) and the
 * link side ({@link LinkHub}) alike: how a vanished peer is found, the rule for running out of
 * descriptors, and the limits on the log lines a client causes (docs/reliability.md).
 */
public interface SocketRules {

    /** How control connections and links find a peer that vanished. */
    KeepAlive keepAlive();

    /** Out of descriptors: give some back, try once more. */
    Descriptors descriptors();

    /** An INFO line a client caused (an operator's FORCE), written to {@code log} within the same limits as the WARNINGs. */
    void note(Logger log, String category, InetAddress client, String message);

    /**
     * An INFO line of the server's about what a client did (its control connection lost), within
     * the limit on such lines per kind (docs/reliability.md).
     */
    void say(Logger log, String kind, InetAddress client, String message);

    /** A WARNING a client caused, written to {@code log} within the limit per client (docs/reliability.md); {@code cause} may be null. */
    void warn(Logger log, String category, InetAddress client, String message, Throwable cause);
}
