package org.usarsim.wss.app;

import java.io.IOException;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.usarsim.wss.hub.FixedSetup;
import org.usarsim.wss.hub.core.DeclaredRobot;
import org.usarsim.wss.hub.core.FixedPort;
import org.usarsim.wss.model.Setting;

/**
 * The keys of declared robots and fixed ports (docs/fixed-ports.md): {@code wss.robot.NAME = ADDRESS}
 * (an IP address, 127.0.0.1 when empty), {@code wss.fixed} and {@code wss.udpIdleSeconds}, read
 * into a {@link FixedSetup} and checked together. Every problem is one line naming the key and its value.
 */
final class FixedPorts {

    /** The prefix of a declared robot's key: {@code wss.robot.Scout = 10.0.0.7}. */
    static final String ROBOT = "wss.robot.";
    static final String KEY = "wss.fixed";
    static final String UDP_IDLE = "wss.udpIdleSeconds";
    /** A declared robot's address when its value is empty. */
    static final String LOCAL = "127.0.0.1";

    private FixedPorts() {
    }

    /**
     * The setup these values give.
     *
     * @param robots      each {@code wss.robot.*} key with its value
     * @param controlPort the control port (wss.port): no fixed TCP port may take it
     * @throws IllegalArgumentException {@code wss.fixed = '...' is not ...: why}, or as much for a {@code wss.robot.*} key
     */
    static FixedSetup setup(Map<String, String> robots, String fixed, int udpIdleSeconds, int controlPort, InetAddress bindAddress) {
        List<DeclaredRobot> declared = new ArrayList<>();
        for (Map.Entry<String, String> entry : robots.entrySet()) {
            DeclaredRobot robot = robot(entry.getKey(), entry.getValue());
            if (!reachable(robot.address(), bindAddress)) {
                throw new IllegalArgumentException(entry.getKey() + " = '" + entry.getValue() + "' is an "
                        + family(robot.address()) + " address, but the WSS ports listen on the " + family(bindAddress)
                        + " address wss.bindAddress = " + bindAddress.getHostAddress()
                        + " (its fixed ports could neither hear it nor reach it: give an " + family(bindAddress)
                        + " address, or set wss.bindAddress to the wildcard 0.0.0.0)");
            }
            declared.add(robot);
        }
        List<FixedPort> ports;
        try {
            ports = FixedPort.listOf(fixed);
        } catch (IllegalArgumentException e) {
            throw refused(fixed, e.getMessage());
        }
        Set<String> names = declared.stream().map(DeclaredRobot::name).collect(Collectors.toSet());
        Map<String, FixedPort> numbers = new HashMap<>();
        Map<String, FixedPort> keys = new HashMap<>();
        for (FixedPort port : ports) {
            for (String robot : List.of(port.key().from(), port.key().to())) {
                if (!names.contains(robot)) {
                    throw refused(fixed, port + ": " + robot + " is not declared (add " + ROBOT + robot + " = ADDRESS)");
                }
            }
            FixedPort before = numbers.put(port.transport() + ":" + port.number(), port);
            if (before != null) {
                throw refused(fixed, port + " and " + before + " take the same " + port.transport().word() + " port "
                        + port.number());
            }
            FixedPort sameKey = keys.put(port.transport() + ":" + port.key(), port);
            if (sameKey != null) {
                throw refused(fixed, port + " and " + sameKey + " are the same way to the same port: one fixed port is enough");
            }
            if (port.transport() == FixedPort.Transport.TCP && port.number() == controlPort) {
                throw refused(fixed, port + " takes the control port (wss.port = " + controlPort + ")");
            }
        }
        return new FixedSetup(declared, ports, udpIdleSeconds);
    }

    private static DeclaredRobot robot(String key, String value) {
        String name = key.substring(ROBOT.length());
        if (name.isEmpty() || name.contains("->") || name.chars().anyMatch(c -> Character.isWhitespace(c) || "{}:,".indexOf(c) >= 0)) {
            throw new IllegalArgumentException(key + " = '" + value + "' does not declare a robot: '" + name
                    + "' is not a robot name (not empty, without whitespace, braces, ':', ',' or '->')");
        }
        String address = value.isBlank() ? LOCAL : value.strip();
        List<InetAddress> one = address.contains(",") ? null : Setting.addressList(address);
        if (one == null) {
            throw new IllegalArgumentException(key + " = '" + value + "' is not an IP address (written as numbers, not 0.0.0.0;"
                    + " empty: " + LOCAL + ")");
        }
        return new DeclaredRobot(name, one.get(0));
    }

    /**
     * Whether the WSS ports on {@code bindAddress} can hear a robot at {@code address} and reach it:
     * on the wildcard (0.0.0.0 or ::, both families), always; on one address, when it is of the
     * robot's family (IPv4 or IPv6).
     */
    private static boolean reachable(InetAddress address, InetAddress bindAddress) {
        return bindAddress.isAnyLocalAddress() || family(address).equals(family(bindAddress));
    }

    private static String family(InetAddress address) {
        return address instanceof java.net.Inet6Address ? "IPv6" : "IPv4";
    }

    /**
     * Refuses a fixed port whose number something on this machine already holds (on the address
     * the WSS ports listen on): bound for a moment, then let go, before anything is started.
     *
     * @throws IllegalArgumentException {@code wss.fixed = '...' is not ...: tcp A->B:1883@11883: port 11883 is in use (why)}
     */
    static void checkFree(FixedSetup setup, String fixed, InetAddress bindAddress) {
        for (FixedPort port : setup.ports()) {
            InetSocketAddress at = new InetSocketAddress(bindAddress, port.number());
            try {
                if (port.transport() == FixedPort.Transport.TCP) {
                    try (ServerSocket socket = new ServerSocket()) {
                        socket.setReuseAddress(true);
                        socket.bind(at);
                    } catch (IOException e) {
                        if (listens(at)) {
                            throw e;
                        } // else: only the last run's connections in TIME_WAIT, which the port's own sockets share the number with
                    }
                } else {
                    try (DatagramSocket socket = new DatagramSocket(null)) {
                        socket.bind(at);
                    }
                }
            } catch (IOException e) {
                throw refused(fixed, port + ": " + port.transport().word() + " port " + port.number() + " is in use ("
                        + e.getMessage() + ")");
            }
        }
    }

    /**
     * Whether something accepts connections at the address (the loopback address for the wildcard):
     * a bind refused because of a previous run's connections still in TIME_WAIT (their listener
     * shared its number, as a WSS port's sockets do) is not a port in use.
     */
    private static boolean listens(InetSocketAddress at) {
        InetSocketAddress target = at.getAddress().isAnyLocalAddress()
                ? new InetSocketAddress(InetAddress.getLoopbackAddress(), at.getPort()) : at;
        try (java.net.Socket probe = new java.net.Socket()) {
            probe.connect(target, 1000);
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    /**
     * What {@code --print-ports} prints: each fixed port on its line, in the order written, saying
     * where its source robot's programs connect (or send) instead of the target's address and port:
     * {@code tcp Scout->Base:1883@11883: Scout (127.0.0.1) connects to the WSS at 127.0.0.1:11883 for Base (10.0.0.8) port 1883}.
     *
     * @param bindAddress the address the WSS ports listen on (the wildcard: any address of this machine)
     */
    static List<String> lines(FixedSetup setup, InetAddress bindAddress) {
        Map<String, String> addresses = new HashMap<>();
        setup.robots().forEach(robot -> addresses.put(robot.name(), robot.address().getHostAddress()));
        List<String> lines = new ArrayList<>();
        for (FixedPort port : setup.ports()) {
            String wss = bindAddress.isAnyLocalAddress()
                    ? "port " + port.number() + " (any address of this machine)"
                    : bindAddress.getHostAddress() + ":" + port.number();
            String verb = port.transport() == FixedPort.Transport.TCP ? "connects to" : "sends to";
            lines.add(port + ": " + port.key().from() + " (" + addresses.get(port.key().from()) + ") " + verb + " the WSS at " + wss
                    + " for " + port.key().to() + " (" + addresses.get(port.key().to()) + ") port " + port.key().targetPort());
        }
        return lines;
    }

    private static IllegalArgumentException refused(String fixed, String why) {
        return new IllegalArgumentException(KEY + " = '" + fixed + "' is not " + FixedPort.WORDS + ": " + why);
    }
}
