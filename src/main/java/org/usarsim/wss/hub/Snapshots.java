package org.usarsim.wss.hub;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.usarsim.wss.hub.core.CloseReason;
import org.usarsim.wss.hub.core.Connection;
import org.usarsim.wss.hub.core.HubCore;
import org.usarsim.wss.hub.core.OrderedPair;
import org.usarsim.wss.hub.core.PairCondition;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.hub.core.PairStats;
import org.usarsim.wss.hub.core.RegisteredRobot;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.hub.udp.UdpRelay;
import org.usarsim.wss.shaping.Airtime;

/**
 * How a {@link HubSnapshot} is taken: what the core holds is copied under the hub's lock
 * ({@link #copy}), then the model is asked for each pair's strength and distance after it
 * ({@link #complete}), and every list is sorted.
 */
final class Snapshots {

    /** What the core holds, copied under the hub's lock. */
    record Copied(List<HubSnapshot.RobotEntry> robots, List<HubSnapshot.PortEntry> ports, List<HubSnapshot.LinkEntry> links,
            List<PairStats> pairStats, Map<OrderedPair, PairCondition> conditions) {
    }

    private Snapshots() {
    }

    /** Under the hub's lock. @param airtime the robots' radios, or null when links are not shaped */
    static Copied copy(HubCore core, Airtime airtime, List<UdpRelay> relays, long nowNs) {
        List<HubSnapshot.RobotEntry> robots = new ArrayList<>();
        for (RegisteredRobot robot : core.robots()) {
            double inUse = airtime == null ? Double.NaN : airtime.inUse(robot.name(), nowNs);
            robots.add(new HubSnapshot.RobotEntry(robot.name(), robot.address().getHostAddress(), robot.ports(), inUse));
        }
        List<HubSnapshot.PortEntry> ports = new ArrayList<>();
        List<HubSnapshot.LinkEntry> links = new ArrayList<>();
        for (WssPort port : core.ports()) {
            var key = port.key;
            ports.add(new HubSnapshot.PortEntry(key.from(), key.to(), key.targetPort(), port.number, port.listening(),
                    core.isFixed(key) ? HubSnapshot.PortKind.FIXED_TCP : HubSnapshot.PortKind.DNS));
            for (Connection link : port.links()) {
                if (link.isEstablished() && !link.isClosed()) {
                    links.add(new HubSnapshot.LinkEntry(key.from(), key.to(), key.targetPort(), port.number, link.outgoingPort()));
                }
            }
        }
        Map<OrderedPair, PairCondition> conditions = core.conditions();
        for (UdpRelay relay : relays) {
            var key = relay.port().key();
            PairCondition up = conditions.get(new OrderedPair(key.from(), key.to()));
            ports.add(new HubSnapshot.PortEntry(key.from(), key.to(), key.targetPort(), relay.number(), up != null && up.passes(),
                    HubSnapshot.PortKind.FIXED_UDP));
        }
        return new Copied(robots, ports, links, core.pairStats(nowNs), conditions);
    }

    /** After the lock: the pairs' rows (the model asked here), every list sorted. */
    static HubSnapshot complete(Copied copied, ModelAnswers model, long nowNs) {
        List<HubSnapshot.PairEntry> pairs = new ArrayList<>();
        Set<String> registered = new HashSet<>();
        copied.robots().forEach(robot -> registered.add(robot.name()));
        for (PairStats pair : copied.pairStats()) {
            String first = pair.pair.first();
            String second = pair.pair.second();
            PairState state = registered.contains(first) && registered.contains(second) ? pair.state() : PairState.GONE;
            double[] rates = pair.rates(nowNs);
            CloseReason lastClose = pair.lastClose();
            pairs.add(new HubSnapshot.PairEntry(first, second, state, model.strength(first, second),
                    model.distance(first, second), pair.bytesFirstToSecond(), pair.bytesSecondToFirst(), rates[0], rates[1],
                    pair.connections(), pair.breaks(), pair.resumes(), pair.upShare(nowNs),
                    lastClose == null ? null : lastClose.toString(),
                    // A pair that cannot talk has no rate: a broken pair's last one would read as if it had.
                    state.isUp() ? rateOf(copied.conditions(), first, second) : 0,
                    state.isUp() ? rateOf(copied.conditions(), second, first) : 0,
                    pair.udpFrom(first).read(), pair.udpFrom(second).read()));
        }
        List<HubSnapshot.RobotEntry> robots = new ArrayList<>(copied.robots());
        List<HubSnapshot.PortEntry> ports = new ArrayList<>(copied.ports());
        List<HubSnapshot.LinkEntry> links = new ArrayList<>(copied.links());
        robots.sort(Comparator.comparing(HubSnapshot.RobotEntry::name));
        ports.sort(Comparator.comparing(HubSnapshot.PortEntry::from).thenComparing(HubSnapshot.PortEntry::to)
                .thenComparingInt(HubSnapshot.PortEntry::targetPort).thenComparing(HubSnapshot.PortEntry::kind));
        links.sort(Comparator.comparing(HubSnapshot.LinkEntry::from).thenComparing(HubSnapshot.LinkEntry::to)
                .thenComparingInt(HubSnapshot.LinkEntry::targetPort).thenComparingInt(HubSnapshot.LinkEntry::outgoingPort));
        pairs.sort(Comparator.comparing(HubSnapshot.PairEntry::first).thenComparing(HubSnapshot.PairEntry::second));
        return new HubSnapshot(robots, ports, links, pairs);
    }

    private static long rateOf(Map<OrderedPair, PairCondition> conditions, String from, String to) {
        PairCondition condition = conditions.get(new OrderedPair(from, to));
        return condition == null ? 0 : condition.bitsPerSecond();
    }
}
