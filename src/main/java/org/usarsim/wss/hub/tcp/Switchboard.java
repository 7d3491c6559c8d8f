package org.usarsim.wss.hub.tcp;

import java.net.InetAddress;
import java.nio.channels.SocketChannel;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.HubCore;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.model.Replay;

/**
 * What the socket classes ask of the hub, and all they know of it: the control sessions' commands,
 * a connection accepted on a WSS port, a link's start and end, and the limited WARNINGs.
 */
public interface Switchboard {

    // ---- control connections ----

    /** INIT: false when the name stays taken. */
    boolean register(String name, InetAddress address, List<Integer> ports, ControlSession session);

    /** The control connection closed: the robot leaves. */
    void deregister(String name, ControlSession session);

    /** Whether a control connection from this address may use the operator command (wss.operators). */
    boolean isOperator(InetAddress address);

    /** GETSS: the model's strength; empty when {@code to} is not registered. */
    OptionalDouble signalStrength(String from, String to);

    /** DNS. */
    HubCore.DnsResult dns(String from, String to, int targetPort);

    /** REVERSEDNS: the source robot of the link whose outgoing port leads to {@code asker}, or null. */
    String reverseDns(String asker, int port);

    /** FORCE ... {State Down|Up}. */
    void force(String robotA, String robotB, Force force);

    /** FORCE ... {State Up} {Rate r} {Delay d}: up, with the pair's rate and delay pinned. */
    void force(String robotA, String robotB, Force force, RatePin pin);

    /** FORCE ... {State Model}. */
    void release(String robotA, String robotB);

    /** REPLAY: the model's replay controls; empty when the model replays nothing. */
    Optional<Replay> replay();

    // ---- WSS ports and links ----

    /** A listener of the port's {@code epoch} accepted a connection: forward it, or close it and say why. */
    void accepted(WssPort port, int epoch, SocketChannel socket);

    /** The link reached its target; returns once that is delivered to the listeners, so its data follows it. */
    void established(Link link);

    /** The link's thread is ending. */
    void linkEnded(Link link, boolean wasEstablished);

    /**
     * Descriptors ran short (a bind or an accept failed with "Too many open files"): the hub
     * forgets remembered ports of robots that left, the longest gone first, before it refuses a
     * robot that is here. Never called under the hub's lock nor on the selector's thread.
     *
     * @return true when some were given back: try once more
     */
    boolean descriptorsShort();

    /** How control connections and links find a peer that vanished. */
    KeepAlive keepAlive();

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
