package org.usarsim.wss.hub.core;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.Map;

/**
 * Whether a connection accepted on a WSS port may be forwarded, asked twice: before the hub opens
 * the link's sockets ({@link #admit}: a refused connection opens nothing) and once they are open,
 * when the link is committed to the port ({@link #commit}). Part of the {@link HubCore}, under its lock.
 */
final class Admissions {

    private final String modelName;
    private final boolean matchSourceAddress;
    /** The robots registered now (none once the core closed). */
    private final Map<String, RegisteredRobot> robots;
    /** The core's ports (none once it closed). */
    private final Ports ports;
    private final Pairs pairs;

    Admissions(String modelName, boolean matchSourceAddress, Map<String, RegisteredRobot> robots, Ports ports, Pairs pairs) {
        this.modelName = modelName;
        this.matchSourceAddress = matchSourceAddress;
        this.robots = robots;
        this.ports = ports;
        this.pairs = pairs;
    }

    /** The first question: where to, with the pair's counters and live conditions, or why not. */
    Admission admit(WssPort port, int epoch, InetAddress peer, boolean allowed, long nowNs, Changes out) {
        PortKey key = port.key;
        String refusal = refusal(port, epoch, peer, allowed);
        if (refusal != null) {
            return new Admission(refusal, null, null, null, null);
        }
        InetSocketAddress target = new InetSocketAddress(robots.get(key.to()).address(), key.targetPort());
        PairStats pairStats = pairs.seen(key.pair(), nowNs, out);
        OrderedPair up = new OrderedPair(key.from(), key.to());
        return new Admission(null, target, pairStats, pairs.condition(up), pairs.condition(up.reversed()));
    }

    /** The second: commits the link to the port, or says why not. */
    String commit(WssPort port, int epoch, InetAddress peer, boolean allowed, Connection link) {
        String refusal = refusal(port, epoch, peer, allowed);
        if (refusal == null) {
            port.addLink(link);
        }
        return refusal;
    }

    /** Why a connection on the port cannot be forwarded now, or null when it can. */
    private String refusal(WssPort port, int epoch, InetAddress peer, boolean allowed) {
        PortKey key = port.key;
        RegisteredRobot source = robots.get(key.from());
        if (ports.get(key) != port || !port.listensWith(epoch) || source == null || !robots.containsKey(key.to())) {
            return "the port no longer listens";
        }
        if (matchSourceAddress && !peer.equals(source.address())) {
            return "the connection came from " + peer.getHostAddress() + " but " + key.from()
                    + " registered from " + source.address().getHostAddress();
        }
        if (!pairs.talks(key.pair(), allowed)) {
            return pairs.forced(key.pair()) == Force.DOWN ? key.pair() + " is forced down"
                    : modelName + " does not allow " + key.from() + " -> " + key.to() + " now";
        }
        return null;
    }
}
