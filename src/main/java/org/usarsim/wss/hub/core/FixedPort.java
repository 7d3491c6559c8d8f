package org.usarsim.wss.hub.core;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A WSS port nobody asked a DNS for (docs/fixed-ports.md): made at Start and kept until Stop,
 * {@code number} on the WSS is {@code key.from()}'s way to {@code key.to()}'s {@code key.targetPort()},
 * by TCP (a stream forwarded as a DNS'd port's) or UDP (datagrams relayed, per sender).
 * {@code wss.fixed} writes them {@code [tcp|udp] FROM->TO:PORT@NUMBER}, comma-separated; the
 * grammar exactly (docs/fixed-ports.md, "The grammar of wss.fixed and wss.robot.*"): the transport word in any case
 * and followed by spaces or tabs; spaces and tabs allowed around each item and around {@code ->},
 * {@code :} and {@code @}; FROM and TO robot names (no whitespace, braces, {@code :}, {@code ,},
 * or {@code ->}); PORT and NUMBER decimal digits, 1 to 65535.
 */
public record FixedPort(Transport transport, PortKey key, int number) {

    /** How a fixed port carries what it is sent. */
    public enum Transport {
        TCP, UDP;

        /** As {@code wss.fixed} and the window write it: {@code tcp}, {@code udp}. */
        public String word() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /** What {@link #listOf} accepts, in words. */
    public static final String WORDS = "a comma-separated list of fixed ports [tcp|udp] FROM->TO:PORT@NUMBER"
            + " (Scout->Base:1883@11883, udp Scout->Base:7400@17400; tcp if not said)";

    /** A robot name as wss.robot.NAME allows it: no whitespace, brace, ':' or ',', and no "->" (a '-' is never followed by '>'). */
    private static final String NAME = "((?:[^\\p{javaWhitespace}{}:,\\-]|-(?!>))+)";
    /** Spaces and tabs: the only whitespace an item may hold (a line break, a form feed... is refused). */
    private static final String WS = "[ \\t]*";
    private static final String WORD = "[^\\p{javaWhitespace}]+";
    private static final Pattern ITEM = Pattern.compile(WS + "(?:(" + WORD + ")[ \\t]+)?" + NAME + WS + "->" + WS + NAME + WS + ":" + WS
            + "([^\\p{javaWhitespace}@]+)" + WS + "@" + WS + "(" + WORD + ")" + WS);

    public FixedPort {
        if (number < 1 || number > 65535 || key.targetPort() < 1 || key.targetPort() > 65535) {
            throw new IllegalArgumentException("ports are 1 to 65535");
        }
    }

    /**
     * The fixed ports of {@code text}; empty text, none.
     *
     * @throws IllegalArgumentException naming the item that is not a fixed port and why
     */
    public static List<FixedPort> listOf(String text) {
        List<FixedPort> ports = new ArrayList<>();
        if (text == null || text.isBlank()) {
            return ports;
        }
        for (String raw : text.split(",", -1)) {
            String item = raw.strip();
            Matcher m = ITEM.matcher(raw);
            if (!m.matches()) {
                throw new IllegalArgumentException("'" + item + "' is not [tcp|udp] FROM->TO:PORT@NUMBER");
            }
            Transport transport;
            String word = m.group(1) == null ? "tcp" : m.group(1);
            if (word.equalsIgnoreCase("tcp")) {
                transport = Transport.TCP;
            } else if (word.equalsIgnoreCase("udp")) {
                transport = Transport.UDP;
            } else {
                throw new IllegalArgumentException("'" + item + "': " + word + " is not tcp or udp");
            }
            if (m.group(2).equals(m.group(3))) {
                throw new IllegalArgumentException("'" + item + "': a robot's port to itself");
            }
            int target = port(item, m.group(4));
            int number = port(item, m.group(5));
            ports.add(new FixedPort(transport, new PortKey(m.group(2), m.group(3), target), number));
        }
        return List.copyOf(ports);
    }

    private static int port(String item, String text) {
        if (!text.matches("\\d{1,5}") || Integer.parseInt(text) < 1 || Integer.parseInt(text) > 65535) {
            throw new IllegalArgumentException("'" + item + "': " + text + " is not a port number from 1 to 65535");
        }
        return Integer.parseInt(text);
    }

    /** As {@code wss.fixed} writes it, the transport always said: {@code udp Scout->Base:7400@17400}. */
    @Override
    public String toString() {
        return transport.word() + " " + key.from() + "->" + key.to() + ":" + key.targetPort() + "@" + number;
    }
}
