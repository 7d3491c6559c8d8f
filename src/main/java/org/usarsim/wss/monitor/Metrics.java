package org.usarsim.wss.monitor;

import java.util.EnumMap;
import java.util.Locale;
import java.util.Map;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.hub.core.UdpCounts;

/**
 * GET /metrics: the hub's snapshot and the monitor's own counts in Prometheus' text exposition
 * format 0.0.4 (docs/monitor.md, "Metrics"). A pair's figures are per direction, labelled
 * {@code robot} (the sender) and {@code peer} (the receiver). Pure.
 */
final class Metrics {

    static final String CONTENT_TYPE = "text/plain; version=0.0.4; charset=utf-8";

    /** The monitor's own counts. */
    record Own(int streams, long streamsCut, long eventsDropped, long unauthorized) {
    }

    private final StringBuilder out = new StringBuilder(4096);

    private Metrics() {
    }

    static String text(HubSnapshot hub, Own own, RoutesJson routes) {
        Metrics m = new Metrics();
        m.family("wss_robots", "gauge", "Robots registered now.");
        m.sample("wss_robots", "", hub.robots().size());
        Map<PairState, Integer> states = new EnumMap<>(PairState.class);
        for (PairState state : PairState.values()) {
            states.put(state, 0);
        }
        hub.pairs().forEach(pair -> states.merge(pair.state(), 1, Integer::sum));
        m.family("wss_pairs", "gauge", "Pairs of robots seen, by state (up, broken, forced_down, forced_up, gone).");
        states.forEach((state, count) -> m.sample("wss_pairs", "state=\"" + state.name().toLowerCase(Locale.ROOT) + "\"", count));
        long listening = hub.ports().stream().filter(HubSnapshot.PortEntry::listening).count();
        m.family("wss_ports", "gauge", "WSS ports held, by whether they listen now.");
        m.sample("wss_ports", "listening=\"true\"", listening);
        m.sample("wss_ports", "listening=\"false\"", hub.ports().size() - listening);
        m.family("wss_connections", "gauge", "Connections forwarded now (established links).");
        m.sample("wss_connections", "", hub.links().size());
        m.perDirection(hub, "wss_pair_bytes_total", "counter", "Bytes forwarded from robot to peer since the pair was first seen.",
                PairEntry::bytesFirstToSecond, PairEntry::bytesSecondToFirst);
        m.perDirection(hub, "wss_pair_rate_bytes_per_second", "gauge", "Throughput from robot to peer now (bytes/s).",
                PairEntry::rateFirstToSecond, PairEntry::rateSecondToFirst);
        m.perDirection(hub, "wss_pair_link_rate_bits_per_second", "gauge",
                "With links shaped, the link rate from robot to peer (bit/s); 0 not shaped or cannot talk.",
                PairEntry::linkRateFirstToSecond, PairEntry::linkRateSecondToFirst);
        m.perDirection(hub, "wss_udp_datagrams_total", "counter", "Datagrams the fixed UDP ports delivered from robot to peer.",
                p -> p.udpFirstToSecond().datagrams(), p -> p.udpSecondToFirst().datagrams());
        m.family("wss_udp_dropped_total", "counter",
                "Datagrams of the fixed UDP ports dropped from robot to peer: the pair broken, or its shaped queue full.");
        for (PairEntry pair : hub.pairs()) {
            m.dropped(pair.first(), pair.second(), pair.udpFirstToSecond());
            m.dropped(pair.second(), pair.first(), pair.udpSecondToFirst());
        }
        m.perDirection(hub, "wss_udp_lost_total", "counter", "Datagrams of the fixed UDP ports lost to the signal (wss.shaping.loss).",
                p -> p.udpFirstToSecond().lost(), p -> p.udpSecondToFirst().lost());
        m.family("wss_robots_cut_off", "gauge", "Robots with no route to the base (wss.route.base; 0 without one).");
        m.sample("wss_robots_cut_off", "", routes.cutOff());
        if (!routes.hopsToBase().isEmpty()) {
            m.family("wss_route_hops", "gauge", "Hops of the robot's best route to the base (peer); -1 cut off.");
            routes.hopsToBase().forEach((robot, hops) -> m.sample("wss_route_hops", labels(robot, routes.table().base()), hops));
        }
        m.family("wss_monitor_streams", "gauge", "Event streams (GET /api/events) open now.");
        m.sample("wss_monitor_streams", "", own.streams());
        m.family("wss_monitor_streams_cut_total", "counter", "Event streams cut because their viewer did not read.");
        m.sample("wss_monitor_streams_cut_total", "", own.streamsCut());
        m.family("wss_monitor_events_dropped_total", "counter",
                "Events not delivered: those a cut stream had queued, and hub changes or log lines the monitor's queue had no room for.");
        m.sample("wss_monitor_events_dropped_total", "", own.eventsDropped());
        m.family("wss_monitor_unauthorized_total", "counter", "Requests refused 401: no token or a wrong one.");
        m.sample("wss_monitor_unauthorized_total", "", own.unauthorized());
        return m.out.toString();
    }

    private interface Figure {
        double of(PairEntry pair);
    }

    private void perDirection(HubSnapshot hub, String name, String type, String help, Figure forward, Figure backward) {
        family(name, type, help);
        for (PairEntry pair : hub.pairs()) {
            sample(name, labels(pair.first(), pair.second()), forward.of(pair));
            sample(name, labels(pair.second(), pair.first()), backward.of(pair));
        }
    }

    private void dropped(String robot, String peer, UdpCounts.Reading udp) {
        sample("wss_udp_dropped_total", labels(robot, peer) + ",reason=\"broken\"", udp.droppedBroken());
        sample("wss_udp_dropped_total", labels(robot, peer) + ",reason=\"queue\"", udp.droppedQueue());
    }

    private void family(String name, String type, String help) {
        out.append("# HELP ").append(name).append(' ').append(help).append('\n');
        out.append("# TYPE ").append(name).append(' ').append(type).append('\n');
    }

    private void sample(String name, String labels, double value) {
        out.append(name);
        if (!labels.isEmpty()) {
            out.append('{').append(labels).append('}');
        }
        out.append(' ').append(number(value)).append('\n');
    }

    private static String labels(String robot, String peer) {
        return "robot=\"" + escape(robot) + "\",peer=\"" + escape(peer) + "\"";
    }

    /** A label value as the format asks: backslash, double quote and line feed escaped. */
    static String escape(String value) {
        return value.replace("\\", "\\\\").replace("\"", "\\\"").replace("\n", "\\n");
    }

    private static String number(double value) {
        if (Double.isNaN(value)) {
            return "NaN";
        }
        if (Double.isInfinite(value)) {
            return value > 0 ? "+Inf" : "-Inf";
        }
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? Long.toString((long) value) : Double.toString(value);
    }
}
