package org.usarsim.wss.recording;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.GZIPInputStream;
import java.util.zip.ZipException;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Wall;

/**
 * Reads a recording (docs/replay.md): plain, or gzip when the name ends in {@code .gz}. A file
 * cut short (a crashed run: no {@code end}, a last line without its line end, a poll missing
 * rows, a gzip stream that stops) is read up to its last whole entry; lines with a keyword this
 * version does not know are skipped and counted, as are lines that cannot be read; a file whose
 * first line is not {@code WSS-RECORDING 1} is refused with one line that says why.
 */
public final class RecordingReader {

    private final Path file;
    private final Map<String, String> names = new HashMap<>();
    private final List<Entry.Poll> polls = new ArrayList<>();
    private final List<Entry.Walls> walls = new ArrayList<>();
    private final List<Entry> events = new ArrayList<>();
    private int unknown;
    private int unreadable;
    private String firstProblem;
    private boolean ended;
    private long lastMillis;
    private int lineNumber;

    /** A poll or a set of walls whose rows are still being read. */
    private EntryLines.Line head;
    private final List<ModelPoll.Robot> robots = new ArrayList<>();
    private final List<ModelPoll.Pair> pairs = new ArrayList<>();
    private final List<Wall> wallRows = new ArrayList<>();

    private RecordingReader(Path file) {
        this.file = file;
    }

    /**
     * The recording in {@code file}.
     *
     * @throws RecordingException when it is missing, unreadable, not a recording or of another version
     */
    public static Recording read(Path file) throws RecordingException {
        return new RecordingReader(file).readAll();
    }

    private Recording readAll() throws RecordingException {
        boolean cutShort;
        Header header;
        try (InputStream raw = Files.newInputStream(file);
                InputStream in = file.getFileName().toString().endsWith(".gz") ? new GZIPInputStream(raw, 1 << 16) : raw;
                Reader text = new InputStreamReader(in, StandardCharsets.UTF_8)) {
            Lines lines = new Lines(text);
            header = header(lines);
            cutShort = body(lines);
        } catch (NoSuchFileException e) {
            throw new RecordingException(file + ": no such file");
        } catch (ZipException e) {
            throw new RecordingException(file + " is not a WSS recording (its name ends in .gz but it is not gzip: "
                    + e.getMessage() + ")");
        } catch (IOException e) {
            throw new RecordingException(file + " cannot be read: " + e.getMessage());
        }
        polls.sort(Comparator.comparingLong(Entry.Poll::millis));
        walls.sort(Comparator.comparingLong(Entry.Walls::millis));
        return new Recording(header, polls, walls, events, lastMillis, cutShort || !ended, unknown, unreadable, firstProblem);
    }

    private Header header(Lines lines) throws IOException, RecordingException {
        String first = lines.next();
        lineNumber = 1;
        if (first == null || !first.startsWith(EntryLines.MAGIC + " ")) {
            throw new RecordingException(file + " is not a WSS recording (its first line is not "
                    + EntryLines.MAGIC + " " + EntryLines.VERSION + ")");
        }
        String version = first.substring(EntryLines.MAGIC.length() + 1).strip();
        if (!version.equals(String.valueOf(EntryLines.VERSION))) {
            throw new RecordingException(file + " is a recording of format version " + version + "; this WSS reads version "
                    + EntryLines.VERSION);
        }
        String wss = "unknown";
        String started = "unknown";
        String model = "unknown";
        Map<String, String> settings = new LinkedHashMap<>();
        while (lines.peekHeader()) {
            String line = lines.next();
            lineNumber++;
            String[] words = line.split(" ", 3);
            try {
                switch (words[0]) {
                    case "wss" -> wss = EntryLines.unescape(words[1]);
                    case "started" -> started = EntryLines.unescape(words[1]);
                    case "model" -> model = EntryLines.unescape(words[1]);
                    case "setting" -> settings.put(EntryLines.unescape(words[1]), EntryLines.unescape(words[2]));
                    default -> unknownLine(words[0]);
                }
            } catch (RuntimeException e) {
                unreadable("a header line that cannot be read: " + line);
            }
        }
        return new Header(EntryLines.VERSION, wss, started, model, settings);
    }

    /** Reads the entries; true when the file was cut short (its last line, or a gzip stream, ends early). */
    private boolean body(Lines lines) throws IOException {
        String text;
        try {
            while ((text = lines.next()) != null) {
                lineNumber++;
                if (text.isEmpty()) {
                    continue;
                }
                EntryLines.Line line;
                try {
                    line = EntryLines.read(text);
                } catch (IllegalArgumentException e) {
                    if (lines.lastHadNoEnd()) {
                        return true;
                    }
                    unreadable(e.getMessage());
                    abandonGroup();
                    continue;
                }
                if (lines.lastHadNoEnd()) {
                    return true; // a line without its line end: the run stopped while writing it
                }
                take(line);
            }
        } catch (EOFException e) {
            return true; // a gzip stream that stops
        }
        boolean partial = head != null;
        abandonGroup();
        return partial;
    }

    private void take(EntryLines.Line line) {
        if (head != null && !continues(line)) {
            unreadable("a " + (head instanceof EntryLines.PollHead ? "poll" : "walls") + " at " + head.millis()
                    + " ms with rows missing");
            abandonGroup();
        }
        lastMillis = Math.max(lastMillis, line.millis());
        boolean isRow = line instanceof EntryLines.RobotRow || line instanceof EntryLines.PairRow || line instanceof EntryLines.WallRow;
        if (isRow && head == null) {
            unreadable("a " + (line instanceof EntryLines.WallRow ? "wall" : "poll's") + " row at " + line.millis()
                    + " ms outside its group");
            return;
        }
        if (line instanceof EntryLines.PollHead || line instanceof EntryLines.WallsHead) {
            head = line;
            finishGroup();
        } else if (line instanceof EntryLines.RobotRow row) {
            ModelPoll.Robot robot = row.robot();
            robots.add(new ModelPoll.Robot(name(robot.name()), robot.position(), robot.batteryEmpty()));
            finishGroup();
        } else if (line instanceof EntryLines.PairRow row) {
            ModelPoll.Pair pair = row.pair();
            pairs.add(new ModelPoll.Pair(name(pair.first()), name(pair.second()), pair.strength(), pair.obstacles(), pair.live()));
            finishGroup();
        } else if (line instanceof EntryLines.WallRow row) {
            wallRows.add(row.wall());
            finishGroup();
        } else if (line instanceof EntryLines.Whole whole) {
            if (whole.entry() instanceof Entry.End) {
                ended = true;
            }
            events.add(whole.entry());
        } else if (line instanceof EntryLines.Unknown other) {
            unknownLine(other.keyword());
        }
    }

    /** Whether the line is the next row of the group being read. */
    private boolean continues(EntryLines.Line line) {
        if (line.millis() != head.millis()) {
            return false;
        }
        if (head instanceof EntryLines.PollHead poll) {
            return line instanceof EntryLines.RobotRow && robots.size() < poll.robots() && pairs.isEmpty()
                    || line instanceof EntryLines.PairRow && robots.size() == poll.robots() && pairs.size() < poll.pairs();
        }
        return line instanceof EntryLines.WallRow;
    }

    /** Ends the group once it has all its rows. */
    private void finishGroup() {
        if (head instanceof EntryLines.PollHead poll && robots.size() == poll.robots() && pairs.size() == poll.pairs()) {
            polls.add(new Entry.Poll(poll.millis(), robots, pairs));
            clearGroup();
        } else if (head instanceof EntryLines.WallsHead set && wallRows.size() == set.walls()) {
            walls.add(new Entry.Walls(set.millis(), wallRows));
            clearGroup();
        }
    }

    private void abandonGroup() {
        clearGroup();
    }

    private void clearGroup() {
        head = null;
        robots.clear();
        pairs.clear();
        wallRows.clear();
    }

    private String name(String name) {
        return names.computeIfAbsent(name, n -> n);
    }

    private void unknownLine(String keyword) {
        unknown++;
        if (firstProblem == null) {
            firstProblem = "line " + lineNumber + ": an unknown keyword " + keyword;
        }
    }

    private void unreadable(String why) {
        unreadable++;
        if (firstProblem == null) {
            firstProblem = "line " + lineNumber + ": " + why;
        }
    }

    /** The file's lines, split on '\n' (a '\r' before it dropped), telling whether the last had no line end. */
    private static final class Lines {

        private final Reader in;
        private final char[] buffer = new char[1 << 16];
        private int position;
        private int limit;
        private boolean noEnd;
        private final StringBuilder partial = new StringBuilder(256);

        Lines(Reader in) {
            this.in = in;
        }

        /** The next line, or null at the end of the file. */
        String next() throws IOException {
            partial.setLength(0);
            noEnd = false;
            while (true) {
                if (position == limit) {
                    limit = in.read(buffer);
                    position = 0;
                    if (limit <= 0) {
                        limit = 0;
                        if (partial.length() == 0) {
                            return null;
                        }
                        noEnd = true;
                        return strip(partial.toString());
                    }
                }
                for (int i = position; i < limit; i++) {
                    if (buffer[i] == '\n') {
                        partial.append(buffer, position, i - position);
                        position = i + 1;
                        return strip(partial.toString());
                    }
                }
                partial.append(buffer, position, limit - position);
                position = limit;
            }
        }

        /** Whether the next line is a header line (it does not start with a digit; the body's lines all do). */
        boolean peekHeader() throws IOException {
            if (position == limit) {
                limit = in.read(buffer);
                position = 0;
                if (limit <= 0) {
                    limit = 0;
                    return false;
                }
            }
            return !Character.isDigit(buffer[position]);
        }

        boolean lastHadNoEnd() {
            return noEnd;
        }

        private static String strip(String line) {
            return line.endsWith("\r") ? line.substring(0, line.length() - 1) : line;
        }
    }
}
