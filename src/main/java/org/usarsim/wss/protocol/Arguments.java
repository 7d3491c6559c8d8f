package org.usarsim.wss.protocol;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;

/** Reads the values of a command's fields: robot names and ports, with the errors they get. */
public final class Arguments {

    private static final Pattern DECIMAL = Pattern.compile("[+-]?[0-9]{1,10}");

    private Arguments() {
    }

    /** The {@code Robot} field: present, not empty, no whitespace inside. */
    public static String robot(Command command) throws ProtocolException {
        String name = command.value("Robot");
        if (name == null || name.isEmpty()) {
            throw new ProtocolException(Replies.NAME_MUST_NOT_BE_EMPTY);
        }
        if (name.chars().anyMatch(Character::isWhitespace)) {
            throw new ProtocolException(Replies.NAME_MUST_NOT_CONTAIN_WHITESPACE);
        }
        return name;
    }

    /**
     * INIT's {@code Port} field: a comma-separated list, whitespace around the commas tolerated,
     * duplicates dropped, order kept. A missing or empty field is an empty list (a robot that
     * accepts no connections).
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
            ports.add(checkRange(port));
        }
        return new ArrayList<>(ports);
    }

    /** DNS's optional {@code Port} field: 0 when missing, empty or 0 (the target's first port). */
    public static int targetPort(Command command) throws ProtocolException {
        String value = command.value("Port");
        if (value == null || value.isEmpty()) {
            return 0;
        }
        Integer port = integer(value);
        if (port == null) {
            throw new ProtocolException(Replies.PORT_MUST_BE_INTEGER);
        }
        return port == 0 ? 0 : checkRange(port);
    }

    /** REVERSEDNS's {@code Port} field, as asked; it must be an integer. */
    public static String askedPort(Command command) throws ProtocolException {
        String value = command.value("Port");
        if (value == null || integer(value) == null) {
            throw new ProtocolException(Replies.PORT_MUST_BE_INTEGER);
        }
        return value;
    }

    private static int checkRange(int port) throws ProtocolException {
        if (port < 1 || port > 65535) {
            throw new ProtocolException(Replies.PORT_OUT_OF_RANGE);
        }
        return port;
    }

    /** A decimal integer of ASCII digits with an optional sign, or null. */
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
