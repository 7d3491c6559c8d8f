package org.usarsim.wss.hub.tcp;

import java.nio.channels.SocketChannel;
import org.usarsim.wss.hub.core.WssPort;

/**
 * What the WSS ports' side asks of the hub, and all it knows of it: a connection accepted on a
 * WSS port (from {@link HandOver}), a link's start and end (from {@link Link}).
 */
public interface LinkHub extends SocketRules {

    /** A listener of the port's {@code epoch} accepted a connection: forward it, or close it and say why. */
    void accepted(WssPort port, int epoch, SocketChannel socket);

    /**
     * The link reached its target: runs {@code opened} and announces it, returning once that is
     * delivered to the listeners, so its data follows it, true; or false, announcing nothing and
     * not running {@code opened}, when a step closed the link meanwhile (a FORCE down answered
     * while it connected): it then ends without having been established.
     */
    boolean established(Link link, Runnable opened);

    /** The link's thread is ending. */
    void linkEnded(Link link, boolean wasEstablished);
}
