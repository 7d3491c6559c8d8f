package org.usarsim.wss.protocol;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.OptionalDouble;
import java.util.Set;
import java.util.regex.Pattern;

/** Reads the values of a command's fields: robot names, ports and REPLAY's values, with the errors they get. */
public final class Arguments {

    private static final Pattern DECIMAL = Pattern.compile("[+-]?[0-9]+");
    /** A plain decimal number: no NaN, no Infinity, no hexadecimal, no d or f suffix as Java would take. */
    private static final Pattern NUMBER = Pattern.compile("[-+]?(\\d+(\\.\\d*)?|\\.\\d+)([eE][-+]?\\d+)?");

    /**
     * The longest robot name, in characters (UTF-16 units, as Java counts them): a name is in
     * every log line and event of its robot, so its length bounds theirs (issue 27).
     */
    public static final int MAX_NAME = 256;

    private Arguments() {
    }

    /** The {@code Robot} field: present, not empty, no whitespace inside, at most {@link #MAX_NAME} characters. */
    public static String robot(Command command) throws ProtocolException {
        return name(command.value("Robot"), Replies.NAME_MUST_NOT_BE_EMPTY, Replies.NAME_MUST_NOT_CONTAIN_WHITESPACE,
                Replies.NAME_TOO_LONG);
    }

    /** FORCE's {@code Peer} field, the other robot of the pair: checked as {@link #robot}, with its own reasons. */
    public static String peer(Command command) throws ProtocolException {
        return name(command.value("Peer"), Replies.PEER_NAME_MUST_NOT_BE_EMPTY, Replies.PEER_NAME_MUST_NOT_CONTAIN_WHITESPACE,
                Replies.PEER_NAME_TOO_LONG);
    }

    /**
     * An operator's pair (FORCE, ROUTE): {@code Robot}, then {@code Peer}, each checked as its own,
     * and not the same name ({@code Peer.Must.Not.Be.The.Robot}).
     */
    public static List<String> pair(Command command) throws ProtocolException {
        String robot = robot(command);
        String peer = peer(command);
        if (robot.equals(peer)) {
            throw new ProtocolException(Replies.PEER_MUST_NOT_BE_THE_ROBOT);
        }
        return List.of(robot, peer);
    }

    private static String name(String name, String emptyReason, String whitespaceReason, String tooLongReason)
            throws ProtocolException {
        if (name == null || name.isEmpty()) {
            throw new ProtocolException(emptyReason);
        }
        if (name.chars().anyMatch(Character::isWhitespace)) {
            throw new ProtocolException(whitespaceReason);
        }
        if (name.length() > MAX_NAME) {
            throw new ProtocolException(tooLongReason);
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

    /** REPLAY's {@code Time} field: seconds from 0 to {@code duration}; empty when there is none. */
    public static OptionalDouble replayTime(Command command, double duration) throws ProtocolException {
        String value = command.value("Time");
        if (value == null) {
            return OptionalDouble.empty();
        }
        double seconds = number(value);
        if (!(seconds >= 0 && seconds <= duration)) {
            throw new ProtocolException(Replies.TIME_MUST_BE_0_TO_DURATION);
        }
        return OptionalDouble.of(seconds);
    }

    /** REPLAY's {@code Speed} field: times as fast as recorded, from {@code min} to {@code max}; empty when there is none. */
    public static OptionalDouble replaySpeed(Command command, double min, double max) throws ProtocolException {
        String value = command.value("Speed");
        if (value == null) {
            return OptionalDouble.empty();
        }
        double speed = number(value);
        if (!(speed >= min && speed <= max)) {
            throw new ProtocolException(Replies.SPEED_MUST_BE_0_25_TO_8);
        }
        return OptionalDouble.of(speed);
    }

    /** REPLAY's {@code State} field, {@code Play} or {@code Pause} in any case: true to play; null when there is none. */
    public static Boolean replayPlays(Command command) throws ProtocolException {
        String value = command.value("State");
        if (value == null) {
            return null;
        }
        return switch (value.toLowerCase(Locale.ROOT)) {
            case "play" -> Boolean.TRUE;
            case "pause" -> Boolean.FALSE;
            default -> throw new ProtocolException(Replies.STATE_MUST_BE_PAUSE_OR_PLAY);
        };
    }

    /** A plain decimal number, or NaN (which no range holds). */
    private static double number(String text) {
        return NUMBER.matcher(text).matches() ? Double.parseDouble(text) : Double.NaN;
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
