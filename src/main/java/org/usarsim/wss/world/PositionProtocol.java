package org.usarsim.wss.world;

import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;
import org.usarsim.wss.protocol.Command;
import org.usarsim.wss.protocol.SegmentException;
import org.usarsim.wss.protocol.SegmentParser;

/**
 * USARSim's answers to the two commands the WSS's models send: {@code GETPOS} and
 * {@code GETOBS {From a} {To b}}, and one of the world server's own that USARSim does not know,
 * {@code GETWALLS} (the map draws the walls), command words and keys in any case ({@code getpos},
 * {@code GetObs {from a} {TO b}}) as USARSim matches them, in the segment grammar of
 * {@link SegmentParser}. Every other line has no answer, as in USARSim. The only place a reply of
 * the world server is written.
 */
final class PositionProtocol {

    private PositionProtocol() {
    }

    /** The reply to a line, without its line end, or null when USARSim would say nothing. */
    static String answer(String line, Supplier<Snapshot> now) {
        return switch (SegmentParser.word(line).toUpperCase(Locale.ROOT)) {
            case "GETPOS" -> positions(now.get());
            case "GETOBS" -> obstacles(line, now);
            case "GETWALLS" -> walls(now.get());
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

    /** {@code WALLS {Walls 2} {Wall x1,y1,x2,y2} {Wall ...}}: every wall of the world, in file order. */
    static String walls(Snapshot world) {
        StringBuilder reply = new StringBuilder("WALLS {Walls ").append(world.walls().size()).append('}');
        for (Wall wall : world.walls()) {
            reply.append(" {Wall ").append(metres(wall.x1())).append(',').append(metres(wall.y1())).append(',')
                    .append(metres(wall.x2())).append(',').append(metres(wall.y2())).append('}');
        }
        return reply.toString();
    }

    /**
     * {@code {From a} {To b}} in either order, other segments ignored, the first of each key that has a
     * value counting; null when either is missing or the line is malformed.
     */
    private static String obstacles(String line, Supplier<Snapshot> now) {
        List<Command.Field> fields;
        try {
            fields = SegmentParser.parse(line).fields();
        } catch (SegmentException e) {
            return null;
        }
        String from = first(fields, "From");
        String to = first(fields, "To");
        if (from == null || to == null) {
            return null;
        }
        int count = now.get().obstacles(from, to);
        return "NUMOBS {From " + from + "} {To " + to + "} {ObstCount " + String.format(Locale.ROOT, "%.4f", (double) count) + "}";
    }

    /** The value of the first segment with this key, in any case, and a value; null when there is none. */
    private static String first(List<Command.Field> fields, String key) {
        for (Command.Field field : fields) {
            if (field.key().equalsIgnoreCase(key) && !field.value().isEmpty()) {
                return field.value();
            }
        }
        return null;
    }

    /** Four decimals, never "-0.0000". */
    private static String metres(double value) {
        String text = String.format(Locale.ROOT, "%.4f", value);
        return text.equals("-0.0000") ? "0.0000" : text;
    }
}
