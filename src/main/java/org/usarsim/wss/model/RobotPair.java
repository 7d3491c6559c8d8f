package org.usarsim.wss.model;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/** Two robot names in no particular order, kept in ascending order: one unordered pair, the same whichever way it was named. */
public record RobotPair(String first, String second) {
    /**
     * Not the record's {@code 31 * h(a) + h(b)}: a name's own hash is a sum of powers of 31, so
     * that sum makes R12 -> R34 and R13 -> R24 alike; the 9,900 pairs of a 100-robot mesh had
     * 2,788 hashes between them, and the hub's maps of pairs and ports searched trees of them.
     */
    @Override
    public int hashCode() {
        return first.hashCode() * 0x9E3779B9 + second.hashCode();
    }

    /** What {@link #listOf} accepts, in words. */
    public static final String LIST_WORDS = "a comma-separated list of robot pairs A:B (two different names,"
            + " without whitespace, braces, ':' or ',')";

    /**
     * The pairs of a list such as {@code A:B, C:D} (whitespace around the items allowed, a pair
     * named twice counted once, in either order), or null when the text is not such a list: each
     * item two different robot names, neither empty nor holding whitespace or braces (names a
     * robot cannot register, docs/protocol.md section 1.3).
     */
    public static List<RobotPair> listOf(String text) {
        Set<RobotPair> pairs = new LinkedHashSet<>();
        for (String item : text.split(",", -1)) {
            String[] names = item.strip().split(":", -1);
            if (names.length != 2 || !robotName(names[0]) || !robotName(names[1]) || names[0].equals(names[1])) {
                return null;
            }
            pairs.add(of(names[0], names[1]));
        }
        return List.copyOf(pairs);
    }

    private static boolean robotName(String name) {
        return !name.isEmpty() && name.chars().noneMatch(c -> Character.isWhitespace(c) || c == '{' || c == '}');
    }

    public static RobotPair of(String a, String b) {
        return a.compareTo(b) <= 0 ? new RobotPair(a, b) : new RobotPair(b, a);
    }

    /** Whether the robot is one of the two. */
    public boolean contains(String robot) {
        return first.equals(robot) || second.equals(robot);
    }

    @Override
    public String toString() {
        return first + " <-> " + second;
    }
}
