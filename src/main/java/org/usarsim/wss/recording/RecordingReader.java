package org.usarsim.wss.recording;

import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.GZIPInputStream;
import java.util.zip.ZipException;
import org.usarsim.wss.model.Wall;

/**
 * Reads a recording (docs/replay.md): plain, or gzip when the name ends in {@code .gz}. A file
 * cut short (a crashed run: no {@code end}, a last line without its line end, a poll missing
 * rows, a gzip stream that stops) is read up to its last whole entry; lines with a keyword this
 * version does not know are skipped and counted, as are lines that cannot be read; a file whose
 * first line is not {@code WSS-RECORDING 1} is refused with one line that says why.
 *
 * <p>Quick to open (a 30-minute run of 12 robots is 9,000 polls and 700,000 lines): the file is
 * read into memory whole and every line but a poll's rows is read at once; a poll's rows are
 * checked for their keyword and time now, and their fields read when the poll is first asked for
 * ({@link LazyPolls}).
 */
public final class RecordingReader {

    private final Path file;
    private final List<LazyPolls.At> polls = new ArrayList<>();
    private final List<Entry.Walls> walls = new ArrayList<>();
    private final List<Entry> events = new ArrayList<>();
    /** The names of the robots the polls list, as written (escaped). */
    private final java.util.Set<String> robotFields = new java.util.HashSet<>();
    private int unknown;
    private int unreadable;
    private String firstProblem;
    private boolean ended;
    private long lastMillis;
    private int lineNumber;

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

    /**
     * The recording in {@code file}, refused when it holds no poll (a run of a model with no
     * simulator): what the replay and {@code --export-world} read, with the same words.
     *
     * @throws RecordingException as {@link #read}, and when it holds no poll
     */
    public static Recording readPolled(Path file) throws RecordingException {
        Recording recording = read(file);
        if (recording.polls().isEmpty()) {
            throw new RecordingException(file + " holds no poll (recorded with " + recording.header().model()
                    + "): nothing to replay or export; a recording of a simulator model has one per poll interval");
        }
        return recording;
    }

    private Recording readAll() throws RecordingException {
        Bytes bytes;
        try {
            bytes = bytes();
        } catch (NoSuchFileException e) {
            throw new RecordingException(file + ": no such file");
        } catch (ZipException e) {
            throw new RecordingException(file + " is not a WSS recording (its name ends in .gz but it is not gzip: "
                    + e.getMessage() + ")");
        } catch (IOException e) {
            throw new RecordingException(file + " cannot be read: " + e.getMessage());
        }
        ByteLines lines = new ByteLines(bytes.data, bytes.length);
        Header header = header(lines);
        boolean cutShort = body(lines) || bytes.streamCut;
        polls.sort(Comparator.comparingLong(LazyPolls.At::millis));
        walls.sort(Comparator.comparingLong(Entry.Walls::millis));
        java.util.SortedSet<String> robots = new java.util.TreeSet<>();
        for (String field : robotFields) {
            try {
                robots.add(EntryLines.unescape(field));
            } catch (IllegalArgumentException e) {
                // Said when its poll is read.
            }
        }
        return new Recording(header, new LazyPolls(file, bytes.data, polls), walls, events, robots, lastMillis,
                cutShort || !ended, unknown, unreadable, firstProblem);
    }

    /** The file's bytes, unzipped; a gzip stream that stops early gives what it had. */
    private record Bytes(byte[] data, int length, boolean streamCut) {
    }

    private Bytes bytes() throws IOException {
        if (!file.getFileName().toString().endsWith(".gz")) {
            byte[] data = Files.readAllBytes(file);
            return new Bytes(data, data.length, false);
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream((int) Math.min(Integer.MAX_VALUE - 16, Files.size(file) * 6 + 1024));
        boolean cut = false;
        try (InputStream in = new GZIPInputStream(Files.newInputStream(file), 1 << 16)) {
            byte[] buffer = new byte[1 << 16];
            int n;
            while ((n = in.read(buffer)) > 0) {
                out.write(buffer, 0, n);
            }
        } catch (EOFException e) {
            cut = true; // a gzip stream that stops: what came before it is kept
        }
        return new Bytes(out.toByteArray(), out.size(), cut);
    }

    private Header header(ByteLines lines) throws RecordingException {
        String first = lines.next() ? lines.text() : null;
        lineNumber = 1;
        if (first == null) {
            throw new RecordingException(file + " is empty: not a WSS recording (one starts with " + EntryLines.MAGIC + " "
                    + EntryLines.VERSION + ")");
        }
        if (!first.startsWith(EntryLines.MAGIC + " ")) {
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
        while (lines.nextIsHeader() && lines.next()) {
            String line = lines.text();
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

    /** Reads the entries; true when the file was cut short (its last line without its line end, or a group missing rows at the end). */
    private boolean body(ByteLines lines) {
        while (lines.next()) {
            lineNumber++;
            if (lines.empty()) {
                continue;
            }
            if (lines.lastHadNoEnd()) {
                return true; // a line without its line end: the run stopped while writing it
            }
            EntryLines.Line line;
            try {
                line = EntryLines.read(lines.text());
            } catch (IllegalArgumentException e) {
                unreadable(e.getMessage());
                continue;
            }
            lastMillis = Math.max(lastMillis, line.millis());
            if (line instanceof EntryLines.PollHead poll) {
                if (!pollRows(lines, poll)) {
                    return true;
                }
            } else if (line instanceof EntryLines.WallsHead set) {
                if (!wallRows(lines, set)) {
                    return true;
                }
            } else if (line instanceof EntryLines.Whole whole) {
                if (whole.entry() instanceof Entry.End) {
                    ended = true;
                }
                events.add(whole.entry());
            } else if (line instanceof EntryLines.Unknown other) {
                unknownLine(other.keyword());
            } else {
                unreadable("a row at " + line.millis() + " ms outside its poll or walls");
            }
        }
        return false;
    }

    /** Checks the poll's rows (keyword and time; their fields are read when the poll is asked for); false when the file ends first. */
    private boolean pollRows(ByteLines lines, EntryLines.PollHead poll) {
        String millis = Long.toString(poll.millis());
        int first = lines.nextStart();
        int firstLine = lineNumber + 1;
        for (int row = 0; row < poll.robots() + poll.pairs(); row++) {
            if (!lines.next() || lines.lastHadNoEnd()) {
                return false;
            }
            lineNumber++;
            String keyword = row < poll.robots() ? "robot" : "pair";
            if (!lines.startsWith(millis, keyword)) {
                unreadable("the poll at " + millis + " ms has " + poll.robots() + " robot and " + poll.pairs()
                        + " pair rows; its row " + (row + 1) + " is not a " + keyword + " row at " + millis + " ms");
                lines.back();
                lineNumber--;
                return true;
            }
            if (row < poll.robots()) {
                robotFields.add(lines.field(2));
            }
        }
        polls.add(new LazyPolls.At(poll.millis(), first, firstLine, poll.robots(), poll.pairs()));
        return true;
    }

    /** Reads the walls' rows; false when the file ends first. */
    private boolean wallRows(ByteLines lines, EntryLines.WallsHead set) {
        List<Wall> rows = new ArrayList<>(set.walls());
        for (int row = 0; row < set.walls(); row++) {
            if (!lines.next() || lines.lastHadNoEnd()) {
                return false;
            }
            lineNumber++;
            EntryLines.Line line;
            try {
                line = EntryLines.read(lines.text());
            } catch (IllegalArgumentException e) {
                line = null;
            }
            if (!(line instanceof EntryLines.WallRow wall) || wall.millis() != set.millis()) {
                unreadable("the walls at " + set.millis() + " ms have a row that is not a wall at that time");
                lines.back();
                lineNumber--;
                return true;
            }
            rows.add(wall.wall());
        }
        walls.add(new Entry.Walls(set.millis(), rows));
        return true;
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

    /** The lines of a file's bytes, split on '\n' (a '\r' before it dropped), telling whether the last had no line end. */
    static final class ByteLines {

        private final byte[] data;
        private final int length;
        private int start;
        private int end;
        private int next;
        private int previousNext;
        private boolean noEnd;

        ByteLines(byte[] data, int length) {
            this.data = data;
            this.length = length;
        }

        ByteLines(byte[] data, int from, int length) {
            this(data, length);
            this.next = from;
        }

        /** Moves to the next line; false at the end of the data. */
        boolean next() {
            if (next >= length) {
                return false;
            }
            previousNext = next;
            start = next;
            int i = start;
            while (i < length && data[i] != '\n') {
                i++;
            }
            noEnd = i == length;
            next = noEnd ? length : i + 1;
            end = i > start && data[i - 1] == '\r' ? i - 1 : i;
            return true;
        }

        /** Goes back to before the line {@link #next} moved to (once). */
        void back() {
            next = previousNext;
        }

        int nextStart() {
            return next;
        }

        boolean nextIsHeader() {
            return next < length && (data[next] < '0' || data[next] > '9');
        }

        boolean empty() {
            return end == start;
        }

        boolean lastHadNoEnd() {
            return noEnd;
        }

        String text() {
            return new String(data, start, end - start, StandardCharsets.UTF_8);
        }

        /** The line's field at {@code index} (0: the time), as written; empty when it has fewer. */
        String field(int index) {
            int at = start;
            for (int i = 0; i < index; i++) {
                while (at < end && data[at] != ' ') {
                    at++;
                }
                at++;
            }
            int from = Math.min(at, end);
            while (at < end && data[at] != ' ') {
                at++;
            }
            return new String(data, from, Math.max(0, Math.min(at, end) - from), StandardCharsets.UTF_8);
        }

        /** Whether the line starts with {@code millis keyword }. */
        boolean startsWith(String millis, String keyword) {
            int at = start;
            for (int i = 0; i < millis.length(); i++, at++) {
                if (at >= end || data[at] != millis.charAt(i)) {
                    return false;
                }
            }
            if (at >= end || data[at++] != ' ') {
                return false;
            }
            for (int i = 0; i < keyword.length(); i++, at++) {
                if (at >= end || data[at] != keyword.charAt(i)) {
                    return false;
                }
            }
            return at < end && data[at] == ' ';
        }
    }
}
