package org.usarsim.wss.hub;

import java.util.List;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.hub.core.UdpCounts;

/**
 * The hub's state at one instant, taken under its lock: what a window that starts observing late,
 * or checks itself, shows. Each list is sorted (robots by name, ports and links by from, to, port).
 */
public record HubSnapshot(List<RobotEntry> robots, List<PortEntry> ports, List<LinkEntry> links, List<PairEntry> pairs) {

    public static final HubSnapshot EMPTY = new HubSnapshot(List.of(), List.of(), List.of(), List.of());

    public HubSnapshot {
        robots = List.copyOf(robots);
        ports = List.copyOf(ports);
        links = List.copyOf(links);
        pairs = List.copyOf(pairs);
    }

    /**
     * A registered robot: its name, the address its control connection came from, its accepting
     * ports, and with links shaped the share of its radio's airtime in use over the last second
     * (0..1; NaN when links are not shaped or do not share airtime).
     */
    public record RobotEntry(String name, String address, List<Integer> ports, double airtime) {
        public RobotEntry {
            ports = List.copyOf(ports);
        }

        /** Airtime not known (links not shaped). */
        public RobotEntry(String name, String address, List<Integer> ports) {
            this(name, address, ports, Double.NaN);
        }
    }

    /** How a WSS port came to be: a DNS asked for it, or it is a fixed port of the configuration, TCP or UDP (docs/fixed-ports.md). */
    public enum PortKind {
        DNS("DNS"), FIXED_TCP("fixed TCP"), FIXED_UDP("fixed UDP");

        private final String text;

        PortKind(String text) {
            this.text = text;
        }

        /** As the Connections tab says it. */
        public String text() {
            return text;
        }
    }

    /**
     * A WSS port for connections from one robot to one port of another, whether it listens now (a
     * fixed UDP port: whether it relays, the pair up), and how it came to be.
     */
    public record PortEntry(String from, String to, int targetPort, int wssPort, boolean listening, PortKind kind) {

        /** A DNS'd port. */
        public PortEntry(String from, String to, int targetPort, int wssPort, boolean listening) {
            this(from, to, targetPort, wssPort, listening, PortKind.DNS);
        }
    }

    /** An established connection through a WSS port, with the WSS's outgoing port to the target. */
    public record LinkEntry(String from, String to, int targetPort, int wssPort, int outgoingPort) {
    }

    /**
     * What is known of one pair of robots (names in ascending order, {@code first} before
     * {@code second}) since it was first seen: its state, the model's strength first -> second
     * (dBm, NaN unknown) and distance (m, NaN unknown), bytes forwarded and current throughput
     * (bytes/s) each way, connections opened, breaks and resumes, the share of time up (0..1) and
     * why its last connection closed (null before any closed); with links shaped, the link's rate
     * each way in bit/s (0: not shaped, or the pair cannot talk: broken, forced down, gone). The
     * state is {@link PairState#GONE} while one of the two robots is not registered.
     */
    public record PairEntry(String first, String second, PairState state, double strength, double distance,
                            long bytesFirstToSecond, long bytesSecondToFirst,
                            double rateFirstToSecond, double rateSecondToFirst,
                            long connections, long breaks, long resumes, double upShare, String lastClose,
                            long linkRateFirstToSecond, long linkRateSecondToFirst,
                            UdpCounts.Reading udpFirstToSecond, UdpCounts.Reading udpSecondToFirst) {

        /** No fixed UDP port counted. */
        public PairEntry(String first, String second, PairState state, double strength, double distance,
                long bytesFirstToSecond, long bytesSecondToFirst, double rateFirstToSecond, double rateSecondToFirst,
                long connections, long breaks, long resumes, double upShare, String lastClose,
                long linkRateFirstToSecond, long linkRateSecondToFirst) {
            this(first, second, state, strength, distance, bytesFirstToSecond, bytesSecondToFirst, rateFirstToSecond,
                    rateSecondToFirst, connections, breaks, resumes, upShare, lastClose, linkRateFirstToSecond, linkRateSecondToFirst,
                    UdpCounts.Reading.NONE, UdpCounts.Reading.NONE);
        }

        /** Links not shaped. */
        public PairEntry(String first, String second, PairState state, double strength, double distance,
                long bytesFirstToSecond, long bytesSecondToFirst, double rateFirstToSecond, double rateSecondToFirst,
                long connections, long breaks, long resumes, double upShare, String lastClose) {
            this(first, second, state, strength, distance, bytesFirstToSecond, bytesSecondToFirst, rateFirstToSecond,
                    rateSecondToFirst, connections, breaks, resumes, upShare, lastClose, 0, 0);
        }
    }
}
