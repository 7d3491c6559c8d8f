package org.usarsim.wss.recording;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalLong;
import org.usarsim.wss.Decimals;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Wall;

/**
 * A recording as a world file (docs/world.md; {@code --export-world}, docs/replay.md "Exporting a
 * world"): a {@code robot} line per robot its polls list, at its first recorded position (with
 * {@code battery T} when a poll showed its battery empty at T), its recorded positions as timed
 * points ({@code at}), only those needed, and the last walls recorded. Pure: a recording in, text
 * out.
 */
public final class WorldExport {

    /**
     * How far from the straight line in time between its neighbours a point may lie and still be
     * left out, in metres: the world's robot is then within this of every recorded position at its
     * time.
     */
    static final double TOLERANCE_METRES = 0.001;

    /** A recorded position at its time. */
    private record Sample(long millis, Position position) {
    }

    /** One robot as the polls listed it: its positions in time, and when its battery was first empty. */
    private static final class Robot {
        final List<Sample> samples = new ArrayList<>();
        OptionalLong emptyAt = OptionalLong.empty();
    }

    private WorldExport() {
    }

    /** The world file of {@code recording}; {@code source} (the recording's file name) is named in its header. */
    public static String worldFile(Recording recording, String source) {
        Map<String, Robot> robots = new LinkedHashMap<>();
        for (Entry.Poll poll : recording.polls()) {
            for (ModelPoll.Robot listed : poll.robots()) {
                Robot robot = robots.computeIfAbsent(listed.name(), name -> new Robot());
                robot.samples.add(new Sample(poll.millis(), listed.position()));
                if (listed.batteryEmpty() && robot.emptyAt.isEmpty()) {
                    robot.emptyAt = OptionalLong.of(poll.millis());
                }
            }
        }
        List<Wall> walls = recording.walls().isEmpty() ? List.of() : recording.walls().get(recording.walls().size() - 1).walls();
        List<String> skipped = new ArrayList<>();
        robots.keySet().removeIf(name -> {
            boolean bad = !worldName(name);
            if (bad) {
                skipped.add(name);
            }
            return bad;
        });
        List<Wall> kept = walls.stream().filter(w -> w.x1() != w.x2() || w.y1() != w.y2()).toList();

        StringBuilder out = new StringBuilder();
        Header header = recording.header();
        out.append("# A world exported from the WSS recording ").append(oneLine(source)).append('\n');
        out.append("# (java -jar wss.jar --export-world; docs/replay.md, \"Exporting a world\").\n");
        out.append("# Recorded by wss ").append(oneLine(header.wssVersion())).append(", started ").append(oneLine(header.started()))
                .append(", model ").append(oneLine(header.model())).append(", ").append(seconds(recording.durationMillis()))
                .append(" s.\n");
        if (recording.cutShort()) {
            out.append("# The recording was cut short (no end line): exported up to its last whole line.\n");
        }
        out.append("# ").append(robots.size()).append(robots.size() == 1 ? " robot" : " robots")
                .append(" at their first recorded positions, then at their recorded positions at their times\n")
                .append("# (a point on the straight line in time between its neighbours left out);\n")
                .append("# ").append(kept.size()).append(kept.size() == 1 ? " wall" : " walls").append(", the last recorded.\n");
        for (String name : skipped) {
            out.append("# left out: the robot ").append(EntryLines.escape(name))
                    .append(", whose name a world file cannot hold (whitespace, #, { or })\n");
        }
        if (kept.size() < walls.size()) {
            int zero = walls.size() - kept.size();
            out.append("# left out: ").append(zero).append(zero == 1 ? " wall" : " walls").append(" of length 0\n");
        }
        if (!robots.isEmpty()) {
            out.append('\n');
        }
        robots.forEach((name, robot) -> {
            out.append("robot ").append(name).append(' ').append(position(robot.samples.get(0).position()));
            robot.emptyAt.ifPresent(millis -> out.append(" battery ").append(seconds(millis)));
            out.append('\n');
        });
        robots.forEach((name, robot) -> {
            out.append('\n');
            for (Sample sample : needed(robot.samples)) {
                out.append("at ").append(name).append(' ').append(seconds(sample.millis())).append(' ')
                        .append(position(sample.position())).append('\n');
            }
        });
        if (!kept.isEmpty()) {
            out.append('\n');
        }
        for (Wall wall : kept) {
            out.append("wall ").append(EntryLines.metres(wall.x1())).append(',').append(EntryLines.metres(wall.y1())).append(' ')
                    .append(EntryLines.metres(wall.x2())).append(',').append(EntryLines.metres(wall.y2()));
            // Its material, when the world file's format can say it (docs/world.md, "wall").
            (wall.material().matches("[A-Za-z0-9_-]+") ? out.append(' ').append(wall.material()) : out).append('\n');
        }
        return out.toString();
    }

    /**
     * The samples a track needs: the first and the last, and each one the straight line in time
     * from the last one kept to a later one would miss by more than {@link #TOLERANCE_METRES} (or
     * would miss another one between them by more). Every sample is then within the tolerance of
     * the track at its time; a robot standing still is two points, or one more for each
     * {@link #MAX_SPAN} samples (a line is checked against every sample it spans: the cap keeps a
     * 30-minute run at 5 polls a second to seconds, not minutes).
     */
    /** The most samples one straight line of a track spans: a minute at 5 polls a second. */
    static final int MAX_SPAN = 300;

    static List<Sample> needed(List<Sample> samples) {
        List<Sample> kept = new ArrayList<>();
        int anchor = 0;
        kept.add(samples.get(0));
        int end = anchor + 1;
        while (end < samples.size()) {
            // Extend the line from the anchor as far as it holds every sample in between.
            if (end + 1 < samples.size() && end + 1 - anchor <= MAX_SPAN && fits(samples, anchor, end + 1)) {
                end++;
                continue;
            }
            kept.add(samples.get(end));
            anchor = end;
            end = anchor + 1;
        }
        return kept;
    }

    /** Whether the line in time from samples[from] to samples[to] passes within the tolerance of every sample between. */
    private static boolean fits(List<Sample> samples, int from, int to) {
        Sample a = samples.get(from);
        Sample b = samples.get(to);
        if (b.millis() == a.millis()) {
            return false; // two positions at one time (never in a recording): keep both
        }
        for (int i = from + 1; i < to; i++) {
            Sample s = samples.get(i);
            double f = (double) (s.millis() - a.millis()) / (b.millis() - a.millis());
            Position p = a.position();
            Position q = b.position();
            Position on = new Position(p.x() + (q.x() - p.x()) * f, p.y() + (q.y() - p.y()) * f, p.z() + (q.z() - p.z()) * f);
            if (on.distanceTo(s.position()) > TOLERANCE_METRES) {
                return false;
            }
        }
        return true;
    }

    /** Whether a world file can hold the name: no whitespace, no {@code #} (a comment), no braces. */
    private static boolean worldName(String name) {
        return !name.isEmpty() && name.chars().noneMatch(c -> Character.isWhitespace(c) || Character.isSpaceChar(c) || c < 0x20
                || c == 0x7f || c == '#' || c == '{' || c == '}');
    }

    private static String position(Position p) {
        return EntryLines.metres(p.x()) + "," + EntryLines.metres(p.y()) + "," + EntryLines.metres(p.z());
    }

    /** Milliseconds as seconds, exactly: {@code 12.4}, {@code 0}, {@code 60}. */
    static String seconds(long millis) {
        return Decimals.plain(BigDecimal.valueOf(millis, 3));
    }

    /** A header field on one comment line: its escaped form (no line break, no control character). */
    private static String oneLine(String text) {
        return EntryLines.escape(text);
    }
}
