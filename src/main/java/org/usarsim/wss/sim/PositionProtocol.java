package org.usarsim.wss.sim;

import java.util.Locale;
import java.util.function.Supplier;

/**
 * USARSim's answers to the two commands the WSS's models send: {@code GETPOS} and
 * {@code GETOBS {From a} {To b}}, command words and keys in any case ({@code getpos},
 * {@code GetObs {from a} {TO b}}) as USARSim matches them. Every other line has no answer, as in
 * USARSim. The only place a reply of the world server is written.
 */
final class PositionProtocol {

    private PositionProtocol() {
    }

    /** The reply to a line, without its line end, or null when USARSim would say nothing. */
    static String answer(String line, Supplier<Snapshot> now) {
        String text = line.strip();
        int end = 0;
        while (end < text.length() && text.charAt(end) != '{' && !Character.isWhitespace(text.charAt(end))) {
            end++;
        }
        String rest = text.substring(end);
        return switch (text.substring(0, end).toUpperCase(Locale.ROOT)) {
            case "GETPOS" -> positions(now.get());
            case "GETOBS" -> obstacles(rest, now);
            default -> null;
        };
    }

    static String positions(Snapshot world) {
        StringBuilder reply = new StringBuilder("POSITIONS {Robots ").append(world.robots().size()).append('}');
        for (RobotAt robot : world.robots()) {
            Point p = robot.position();
            reply.append(" {Name ").append(robot.name())
                    .append(" Location ").append(metres(p.x())).append(',').append(metres(p.y())).append(',').append(metres(p.z()))
                    .append(" BatteryEmpty ").append(robot.batteryEmpty() ? "True" : "False").append('}');
        }
        return reply.toString();
    }

    /** {@code {From a} {To b}} in either order, other segments ignored; null when either is missing or a segment is malformed. */
    private static String obstacles(String segments, Supplier<Snapshot> now) {
        String from = null;
        String to = null;
        int i = 0;
        while (true) {
            while (i < segments.length() && Character.isWhitespace(segments.charAt(i))) {
                i++;
            }
            if (i == segments.length()) {
                break;
            }
            int close = segments.indexOf('}', i);
            if (segments.charAt(i) != '{' || close < 0) {
                return null;
            }
            String[] keyValue = segments.substring(i + 1, close).strip().split("\\s+", 2);
            if (keyValue.length == 2) {
                if (keyValue[0].equalsIgnoreCase("From") && from == null) {
                    from = keyValue[1].strip();
                } else if (keyValue[0].equalsIgnoreCase("To") && to == null) {
                    to = keyValue[1].strip();
                }
            }
            i = close + 1;
        }
        if (from == null || to == null) {
            return null;
        }
        int count = now.get().obstacles(from, to);
        return "NUMOBS {From " + from + "} {To " + to + "} {ObstCount " + String.format(Locale.ROOT, "%.4f", (double) count) + "}";
    }

    /** Four decimals, never "-0.0000". */
    private static String metres(double value) {
        String text = String.format(Locale.ROOT, "%.4f", value);
        return text.equals("-0.0000") ? "0.0000" : text;
    }
}
