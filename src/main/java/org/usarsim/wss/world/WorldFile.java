package org.usarsim.wss.world;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.regex.Pattern;

/**
 * Reads a world file (the format is in docs/world.md): one statement a line, {@code #} starts a
 * comment, blank lines are skipped.
 *
 * <pre>
 * robot NAME X,Y,Z [battery SECONDS]
 * path NAME speed METRES_PER_SECOND loop|once X,Y[,Z] ...
 * at NAME SECONDS X,Y[,Z]
 * wall X1,Y1 X2,Y2 [MATERIAL]
 * </pre>
 *
 * The first mistake stops the reading, with the message {@code FILE:LINE: what is wrong (the line)}.
 */
final class WorldFile {

    /** A plain decimal number: no NaN, no Infinity, no hexadecimal, no d or f suffix as Java would take. */
    private static final Pattern NUMBER = Pattern.compile("[-+]?(\\d+(\\.\\d*)?|\\.\\d+)([eE][-+]?\\d+)?");

    private final String source;
    private final Map<String, WorldRobot> robots = new LinkedHashMap<>();
    private final Map<String, Integer> pathLines = new LinkedHashMap<>();
    /** Each robot's timed points ({@code at} lines) so far, in file order, and the line of its first. */
    private final Map<String, List<Track.TimedPoint>> tracks = new LinkedHashMap<>();
    private final Map<String, Integer> trackLines = new LinkedHashMap<>();
    private final List<Wall> walls = new ArrayList<>();
    private int lineNumber;
    private String line;

    private WorldFile(String source) {
        this.source = source;
    }

    static World read(Path file) throws WorldFileException {
        List<String> lines;
        try {
            lines = Files.readAllLines(file);
        } catch (CharacterCodingException e) {
            throw new WorldFileException(file + ": not UTF-8 text");
        } catch (NoSuchFileException e) {
            throw new WorldFileException(file + ": no such file");
        } catch (IOException e) {
            throw new WorldFileException(file + ": cannot read it: " + e);
        }
        return parse(file.toString(), lines);
    }

    /** The world these lines describe; {@code source} names them in error messages. */
    static World parse(String source, List<String> lines) throws WorldFileException {
        WorldFile file = new WorldFile(source);
        for (String text : lines) {
            file.lineNumber++;
            file.line = text;
            file.statement(text);
        }
        List<WorldRobot> robots = new ArrayList<>();
        for (WorldRobot robot : file.robots.values()) {
            List<Track.TimedPoint> track = file.tracks.get(robot.name());
            robots.add(track == null ? robot
                    : new WorldRobot(robot.name(), robot.start(), new Track(robot.start(), track), robot.batterySeconds()));
        }
        return new World(robots, file.walls);
    }

    private void statement(String text) throws WorldFileException {
        int comment = text.indexOf('#');
        String[] words = (comment < 0 ? text : text.substring(0, comment)).trim().split("\\s+");
        if (words[0].isEmpty()) {
            return;
        }
        switch (words[0]) {
            case "robot" -> robot(words);
            case "path" -> path(words);
            case "at" -> at(words);
            case "wall" -> wall(words);
            default -> throw error("unknown statement '" + words[0] + "'; a line is robot, path, at or wall");
        }
    }

    /** {@code robot NAME X,Y,Z [battery SECONDS]} */
    private void robot(String[] words) throws WorldFileException {
        if (words.length != 3 && words.length != 5) {
            throw error("a robot is 'robot NAME X,Y,Z' or 'robot NAME X,Y,Z battery SECONDS'");
        }
        String name = name(words[1]);
        if (robots.containsKey(name)) {
            throw error("a second robot named " + name);
        }
        double[] start = coordinates(words[2], 3, 3, "the start position X,Y,Z");
        OptionalDouble battery = OptionalDouble.empty();
        if (words.length == 5) {
            keyword(words[3], "battery");
            double seconds = number(words[4], "the battery life in seconds");
            if (seconds < 0) {
                throw error("the battery life must be 0 seconds or more: " + words[4]);
            }
            battery = OptionalDouble.of(seconds);
        }
        robots.put(name, new WorldRobot(name, new Point(start[0], start[1], start[2]), null, battery));
    }

    /** {@code path NAME speed V loop|once X,Y[,Z] ...} */
    private void path(String[] words) throws WorldFileException {
        if (words.length < 6) {
            throw error("a path is 'path NAME speed METRES_PER_SECOND loop|once X,Y[,Z] ...' with at least one waypoint");
        }
        WorldRobot robot = robots.get(words[1]);
        if (robot == null) {
            throw error("a path for " + words[1] + ", which is no robot declared above");
        }
        Integer earlier = pathLines.putIfAbsent(robot.name(), lineNumber);
        if (earlier != null) {
            throw error(robot.name() + " already has a path, on line " + earlier);
        }
        if (trackLines.containsKey(robot.name())) {
            throw error(robot.name() + " already has timed points ('at', from line " + trackLines.get(robot.name())
                    + "): a robot follows a path or timed points, not both");
        }
        keyword(words[2], "speed");
        double speed = number(words[3], "the speed in metres per second");
        if (speed <= 0) {
            throw error("the speed must be above 0 metres per second: " + words[3]);
        }
        boolean loop = switch (words[4]) {
            case "loop" -> true;
            case "once" -> false;
            default -> throw error("expected loop or once, found '" + words[4] + "'");
        };
        Point start = robot.start();
        List<Point> waypoints = new ArrayList<>();
        for (int i = 5; i < words.length; i++) {
            double[] xyz = coordinates(words[i], 2, 3, "a waypoint X,Y or X,Y,Z");
            waypoints.add(new Point(xyz[0], xyz[1], xyz.length == 3 ? xyz[2] : start.z()));
        }
        robots.put(robot.name(), new WorldRobot(robot.name(), start, new Route(start, waypoints, speed, loop), robot.batterySeconds()));
    }

    /** {@code at NAME SECONDS X,Y[,Z]}: one timed point of the robot's track, later than its point before. */
    private void at(String[] words) throws WorldFileException {
        if (words.length != 4) {
            throw error("a timed point is 'at NAME SECONDS X,Y[,Z]'");
        }
        WorldRobot robot = robots.get(words[1]);
        if (robot == null) {
            throw error("a timed point for " + words[1] + ", which is no robot declared above");
        }
        Integer path = pathLines.get(robot.name());
        if (path != null) {
            throw error(robot.name() + " already has a path, on line " + path + ": a robot follows a path or timed points, not both");
        }
        double seconds = number(words[2], "the time in seconds");
        if (seconds < 0) {
            throw error("the time must be 0 seconds or more: " + words[2]);
        }
        List<Track.TimedPoint> track = tracks.computeIfAbsent(robot.name(), name -> new ArrayList<>());
        trackLines.putIfAbsent(robot.name(), lineNumber);
        if (!track.isEmpty() && !(seconds > track.get(track.size() - 1).seconds())) {
            throw error("the times of " + robot.name() + "'s points must grow: " + words[2] + " s is not after "
                    + timeText(track.get(track.size() - 1).seconds()) + " s");
        }
        double[] xyz = coordinates(words[3], 2, 3, "the point X,Y or X,Y,Z");
        track.add(new Track.TimedPoint(seconds, new Point(xyz[0], xyz[1], xyz.length == 3 ? xyz[2] : robot.start().z())));
    }

    /** A time as the file may have written it: no trailing {@code .0}. */
    private static String timeText(double seconds) {
        return seconds == Math.rint(seconds) && Math.abs(seconds) < 1e15 ? Long.toString((long) seconds) : Double.toString(seconds);
    }

    /** {@code wall X1,Y1 X2,Y2 [MATERIAL]} */
    private void wall(String[] words) throws WorldFileException {
        if (words.length != 3 && words.length != 4) {
            throw error("a wall is 'wall X1,Y1 X2,Y2' or 'wall X1,Y1 X2,Y2 MATERIAL'");
        }
        String material = words.length == 4 ? words[3].toLowerCase(java.util.Locale.ROOT) : "";
        if (!material.isEmpty() && !MaterialRules.MATERIAL.matcher(material).matches()) {
            throw error("a wall is 'wall X1,Y1 X2,Y2' or 'wall X1,Y1 X2,Y2 MATERIAL', a material letters, digits, _ and -");
        }
        double[] from = coordinates(words[1], 2, 2, "the wall's first end X1,Y1");
        double[] to = coordinates(words[2], 2, 2, "the wall's second end X2,Y2");
        if (from[0] == to[0] && from[1] == to[1]) {
            throw error("a wall of length 0");
        }
        walls.add(new Wall(from[0], from[1], to[0], to[1], material));
    }

    private String name(String word) throws WorldFileException {
        if (word.indexOf('{') >= 0 || word.indexOf('}') >= 0) {
            throw error("a robot name cannot contain { or }: " + word);
        }
        return word;
    }

    private void keyword(String word, String expected) throws WorldFileException {
        if (!word.equals(expected)) {
            throw error("expected '" + expected + "', found '" + word + "'");
        }
    }

    private double[] coordinates(String word, int least, int most, String what) throws WorldFileException {
        String[] parts = word.split(",", -1);
        if (parts.length < least || parts.length > most) {
            throw error("expected " + what + " (numbers separated by commas, no spaces), found '" + word + "'");
        }
        double[] values = new double[parts.length];
        for (int i = 0; i < parts.length; i++) {
            values[i] = number(parts[i], what);
        }
        return values;
    }

    private double number(String word, String what) throws WorldFileException {
        double value = NUMBER.matcher(word).matches() ? Double.parseDouble(word) : Double.NaN;
        if (!Double.isFinite(value)) {
            throw error("'" + word + "' is not a number, in " + what);
        }
        return value;
    }

    private WorldFileException error(String what) {
        return new WorldFileException(source + ":" + lineNumber + ": " + what + " (" + line.strip() + ")");
    }
}
