package org.usarsim.wss.hub.tcp;

import org.usarsim.wss.hub.core.DnsResult;
import java.net.InetAddress;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.routes.RouteTable;

/**
 * What the control side asks of the hub, and all it knows of it: the commands of the control
 * sessions ({@link ControlSession}), each answered from the hub's state.
 */
public interface ControlHub extends SocketRules {

    /** INIT: false when the name stays taken. */
    boolean register(String name, InetAddress address, List<Integer> ports, ControlSession session);

    /** The control connection closed: the robot leaves. */
    void deregister(String name, ControlSession session);

    /** Whether a control connection from this address may use the operator command (wss.operators). */
    boolean isOperator(InetAddress address);

    /** GETSS: the model's strength; empty when {@code to} is not registered. */
    OptionalDouble signalStrength(String from, String to);

    /** DNS. */
    DnsResult dns(String from, String to, int targetPort);

    /** REVERSEDNS: the source robot of the link whose outgoing port leads to {@code asker}, or null. */
    String reverseDns(String asker, int port);

    /** FORCE ... {State Down|Up}. */
    void force(String robotA, String robotB, Force force);

    /** FORCE ... {State Up} {Rate r} {Delay d}: up, with the pair's rate and delay pinned. */
    void force(String robotA, String robotB, Force force, RatePin pin);

    /** FORCE ... {State Model}. */
    void release(String robotA, String robotB);

    /** ROUTE: the routes as last found (docs/routes.md). */
    RouteTable routes();

    /** REPLAY: the model's replay controls; empty when the model replays nothing. */
    Optional<Replay> replay();
}
