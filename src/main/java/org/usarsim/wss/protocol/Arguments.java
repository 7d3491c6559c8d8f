package org.usarsim.wss.protocol;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;

/** Reads the values of a command's fields: robot names and ports, with the errors they get. */
public final class Arguments {

    private static final Pattern DECIMAL = Pattern.compile("[+-]?[0-9]+");

    private Arguments() {
    }

    /** The {@code Robot} field: present, not empty, no whitespace inside. */
    public static String robot(Command command) throws ProtocolException {
        return name(command.value("Robot"), Replies.NAME_MUST_NOT_BE_EMPTY, Replies.NAME_MUST_NOT_CONTAIN_WHITESPACE);
    }

    /** FORCE's {@code Peer} field, the other robot of the pair: checked as {@link #robot}, with its own reasons. */
    public static String peer(Command command) throws ProtocolException {
        return name(command.value("Peer"), Replies.PEER_NAME_MUST_NOT_BE_EMPTY, Replies.PEER_NAME_MUST_NOT_CONTAIN_WHITESPACE);
    }

    private static String name(String name, String emptyReason, String whitespaceReason) throws ProtocolException {
        if (name == null || name.isEmpty()) {
            throw new ProtocolException(emptyReason);
        }
        if (name.chars().anyMatch(Character::isWhitespace)) {
            throw new ProtocolException(whitespaceReason);
        }
        return name;
    }

    /**
     * INIT's {@code Port} field: a comma-separated list of integers, whitespace around the commas
     * tolerated, duplicates dropped, order kept. A missing or empty field is an empty list (a robot
     * that accepts no connections). Any integer is accepted, as the original does (0, -1, 70000):
     * the robot registers, and a port outside 1..65535 is never dialled (see Robot.resolvePort).
     */
    public static List<Integer> portList(Command command) throws ProtocolException {
        String list = command.value("Port");
        if (list == null || list.isEmpty()) {
            return List.of();
        }
        Set<Integer> ports = new LinkedHashSet<>();
        for (String item : list.split(",", -1)) {
            Integer port = integer(item.strip());
            if (port == null) {
                throw new ProtocolException(Replies.PORTS_MUST_BE_INTEGER);
            }
            ports.add(port);
        }
        return new ArrayList<>(ports);
    }

    /**
     * DNS's optional {@code Port} field: 0 when missing or 0 (the target's first port), else the
     * integer as asked, in range or not. An empty value is not an integer, as in the original.
     */
    public static int targetPort(Command command) throws ProtocolException {
        String value = command.value("Port");
        if (value == null) {
            return 0;
        }
        Integer port = integer(value);
        if (port == null) {
            throw new ProtocolException(Replies.PORT_MUST_BE_INTEGER);
        }
        return port;
    }

    /** REVERSEDNS's {@code Port} field, as asked; it must be an integer. */
    public static String askedPort(Command command) throws ProtocolException {
        String value = command.value("Port");
        if (value == null || integer(value) == null) {
            throw new ProtocolException(Replies.PORT_MUST_BE_INTEGER);
        }
        return value;
    }

    /**
     * A decimal integer of ASCII digits with an optional sign and any number of leading zeros,
     * from -2147483648 to 2147483647 (a 32-bit int, as the original's conversion), or null.
     */
    static Integer integer(String text) {
        if (!DECIMAL.matcher(text).matches()) {
            return null;
        }
        try {
            return Integer.valueOf(text);
        } catch (NumberFormatException e) {
            return null;
        }
    }
}
