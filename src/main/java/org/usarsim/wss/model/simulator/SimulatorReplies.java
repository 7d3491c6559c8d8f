package org.usarsim.wss.model.simulator;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.protocol.Command;
import org.usarsim.wss.protocol.SegmentException;
import org.usarsim.wss.protocol.SegmentParser;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Wall;

/**
 * Reads the simulator's replies:
 * {@code POSITIONS {Robots 2} {Name R1 Location 1.25,-3.0,0.45 BatteryEmpty False} {Name R2 ...}} and
 * {@code NUMOBS {From a} {To b} {ObstCount 3.0000}}, and the world server's
 * {@code WALLS {Walls 1} {Wall x1,y1,x2,y2}}, in the segment grammar of
 * {@link SegmentParser} (extra whitespace tolerated). Fields it does not use are ignored; anything else
 * is a {@link SimulatorReplyException} naming what is wrong.
 */
final class SimulatorReplies {

    static final String POSITIONS = "POSITIONS";
    static final String NUMOBS = "NUMOBS";
    static final String WALLS = "WALLS";

    private SimulatorReplies() {
    }

    /** The type of a reply line: its first word. */
    static String type(String line) {
        return SegmentParser.word(line);
    }

    /** The robots of a POSITIONS line, by name, in the order given. */
    static Map<String, ReportedRobot> positions(String line) throws SimulatorReplyException {
        List<List<String>> segments = segments(line, POSITIONS);
        if (segments.isEmpty()) {
            throw malformed(line, "no {Robots n}");
        }
        List<String> count = segments.get(0);
        if (count.size() != 2 || !count.get(0).equals("Robots")) {
            throw malformed(line, "it does not start with {Robots n}");
        }
        int robots;
        try {
            robots = Integer.parseInt(count.get(1));
        } catch (NumberFormatException e) {
            throw malformed(line, "the robot count is not a number");
        }
        if (robots != segments.size() - 1) {
            throw malformed(line, "it says " + robots + " robots but lists " + (segments.size() - 1));
        }
        Map<String, ReportedRobot> result = new LinkedHashMap<>();
        for (List<String> segment : segments.subList(1, segments.size())) {
            ReportedRobot robot = robot(segment, line);
            if (result.put(robot.name(), robot) != null) {
                throw malformed(line, "robot " + robot.name() + " is listed twice");
            }
        }
        return result;
    }

    private static ReportedRobot robot(List<String> segment, String line) throws SimulatorReplyException {
        if (segment.size() % 2 != 0) {
            throw malformed(line, "a robot's fields are not key-value pairs: " + String.join(" ", segment));
        }
        String name = null;
        double[] location = null;
        boolean batteryEmpty = false;
        for (int i = 0; i < segment.size(); i += 2) {
            String value = segment.get(i + 1);
            switch (segment.get(i)) {
                case "Name" -> name = value;
                case "Location" -> location = location(value, line);
                case "BatteryEmpty" -> batteryEmpty = bool(value, line);
                default -> {
                    // Fields we do not use (a newer simulator may add some) are ignored.
                }
            }
        }
        if (name == null || location == null) {
            throw malformed(line, "a robot without Name or Location: {" + String.join(" ", segment) + "}");
        }
        return new ReportedRobot(name, location[0], location[1], location[2], batteryEmpty);
    }

    private static double[] location(String value, String line) throws SimulatorReplyException {
        String[] parts = value.split(",", -1);
        if (parts.length != 3) {
            throw malformed(line, "location " + value + " is not x,y,z");
        }
        double[] xyz = new double[3];
        for (int i = 0; i < 3; i++) {
            try {
                xyz[i] = Double.parseDouble(parts[i]);
            } catch (NumberFormatException e) {
                throw malformed(line, "location " + value + " is not x,y,z");
            }
            if (!Double.isFinite(xyz[i])) {
                throw malformed(line, "location " + value + " is not finite");
            }
        }
        return xyz;
    }

    private static boolean bool(String value, String line) throws SimulatorReplyException {
        if (value.equalsIgnoreCase("True")) {
            return true;
        }
        if (value.equalsIgnoreCase("False")) {
            return false;
        }
        throw malformed(line, "BatteryEmpty " + value + " is not True or False");
    }

    /** A NUMOBS reply: the pair it is for and the count, NaN when the simulator does not know (negative). */
    record ObstacleCount(RobotPair pair, double count) {
    }

    static ObstacleCount obstacles(String line) throws SimulatorReplyException {
        Map<String, String> fields = new LinkedHashMap<>();
        for (List<String> segment : segments(line, NUMOBS)) {
            if (segment.size() != 2) {
                throw malformed(line, "{" + String.join(" ", segment) + "} is not {Key Value}");
            }
            fields.put(segment.get(0), segment.get(1));
        }
        String from = fields.get("From");
        String to = fields.get("To");
        String count = fields.get("ObstCount");
        if (from == null || to == null || count == null) {
            throw malformed(line, "it needs From, To and ObstCount");
        }
        double value;
        try {
            value = Double.parseDouble(count);
        } catch (NumberFormatException e) {
            throw malformed(line, "ObstCount " + count + " is not a number");
        }
        return new ObstacleCount(RobotPair.of(from, to), value >= 0 && Double.isFinite(value) ? value : Double.NaN);
    }

    /** The walls of a WALLS line, in the order given. */
    static List<Wall> walls(String line) throws SimulatorReplyException {
        List<List<String>> segments = segments(line, WALLS);
        if (segments.isEmpty() || segments.get(0).size() != 2 || !segments.get(0).get(0).equals("Walls")) {
            throw malformed(line, "it does not start with {Walls n}");
        }
        int walls;
        try {
            walls = Integer.parseInt(segments.get(0).get(1));
        } catch (NumberFormatException e) {
            throw malformed(line, "the wall count is not a number");
        }
        if (walls != segments.size() - 1) {
            throw malformed(line, "it says " + walls + " walls but lists " + (segments.size() - 1));
        }
        List<Wall> result = new ArrayList<>();
        for (List<String> segment : segments.subList(1, segments.size())) {
            String[] parts = segment.size() == 2 && segment.get(0).equals("Wall") ? segment.get(1).split(",", -1) : new String[0];
            if (parts.length != 4) {
                throw malformed(line, "{" + String.join(" ", segment) + "} is not {Wall x1,y1,x2,y2}");
            }
            double[] xy = new double[4];
            for (int i = 0; i < 4; i++) {
                try {
                    xy[i] = Double.parseDouble(parts[i]);
                } catch (NumberFormatException e) {
                    xy[i] = Double.NaN;
                }
                if (!Double.isFinite(xy[i])) {
                    throw malformed(line, "wall " + segment.get(1) + " is not four finite numbers");
                }
            }
            result.add(new Wall(xy[0], xy[1], xy[2], xy[3]));
        }
        return List.copyOf(result);
    }

    /**
     * The {...} segments after the type word, each as its whitespace-separated words (the key first):
     * a robot's segment holds several key-value pairs, {@code {Name R1 Location 1,2,3}}.
     */
    private static List<List<String>> segments(String line, String type) throws SimulatorReplyException {
        if (!type(line).equals(type)) {
            throw malformed(line, "it is not a " + type + " reply");
        }
        List<Command.Field> fields;
        try {
            fields = SegmentParser.parse(line).fields();
        } catch (SegmentException e) {
            throw malformed(line, e.problem().description());
        }
        List<List<String>> segments = new ArrayList<>();
        for (Command.Field field : fields) {
            List<String> words = new ArrayList<>();
            words.add(field.key());
            if (!field.value().isEmpty()) {
                words.addAll(List.of(field.value().split("\\p{javaWhitespace}+")));
            }
            segments.add(words);
        }
        return segments;
    }

    private static SimulatorReplyException malformed(String line, String why) {
        String shown = line.length() > 200 ? line.substring(0, 200) + "..." : line;
        return new SimulatorReplyException("malformed reply (" + why + "): " + shown);
    }
}
