package org.usarsim.wss.hub.core;

/**
 * A forwarded connection as the core sees it: the core counts a port's connections, finds one by
 * the WSS's outgoing port (REVERSEDNS), and says which to close; the socket work is the link's.
 */
public interface Connection {

    /** The local port of the WSS's socket to the target: what the target sees as its peer's port. */
    int outgoingPort();

    /** Whether the WSS reached the target (what the window lists as established). */
    boolean isEstablished();

    boolean isClosed();

    /** Closes both ends, saying why (the pair's last close, unless another reason came first). */
    void close(CloseReason reason);
}
