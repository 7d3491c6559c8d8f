package org.usarsim.wss.recording;

import java.io.ByteArrayOutputStream;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.Decimals;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.protocol.Strengths;

/**
 * The one place where a recording's lines are written and read (docs/replay.md, "The format"):
 * the header, and each {@link Entry} as its lines, {@code MILLIS KEYWORD FIELDS...} separated by
 * single spaces. Names and setting values are written with {@code %XX} for '%', whitespace and
 * control characters (UTF-8 bytes), so that a field never holds a space or breaks a line.
 */
public final class EntryLines {

    /** The first word of a recording's first line. */
    public static final String MAGIC = "WSS-RECORDING";
    /** The version of the format this build writes and reads. */
    public static final int VERSION = 1;

    private EntryLines() {
    }

    // ---- writing ----

    /** The header's lines, each ended by '\n'. */
    public static void header(StringBuilder out, Header header) {
        out.append(MAGIC).append(' ').append(header.version()).append('\n');
        out.append("wss ").append(escape(header.wssVersion())).append('\n');
        out.append("started ").append(escape(header.started())).append('\n');
        out.append("model ").append(escape(header.model())).append('\n');
        for (Map.Entry<String, String> setting : header.settings().entrySet()) {
            out.append("setting ").append(escape(setting.getKey())).append(' ').append(escape(setting.getValue())).append('\n');
        }
    }

    /** The entry's lines (a poll: its line, then a line per robot and per pair), each ended by '\n'. */
    public static void write(StringBuilder out, Entry entry) {
        long t = entry.millis();
        if (entry instanceof Entry.Poll poll) {
            line(out, t, "poll").append(' ').append(poll.robots().size()).append(' ').append(poll.pairs().size()).append('\n');
            for (ModelPoll.Robot robot : poll.robots()) {
                Position p = robot.position();
                line(out, t, "robot").append(' ').append(escape(robot.name())).append(' ').append(metres(p.x())).append(' ')
                        .append(metres(p.y())).append(' ').append(metres(p.z())).append(' ')
                        .append(robot.batteryEmpty() ? "empty" : "ok").append('\n');
            }
            for (ModelPoll.Pair pair : poll.pairs()) {
                line(out, t, "pair").append(' ').append(escape(pair.first())).append(' ').append(escape(pair.second()))
                        .append(' ').append(Strengths.format(pair.strength())).append(' ').append(count(pair.obstacles()))
                        .append(' ').append(pair.live() ? "up" : "down").append('\n');
            }
        } else if (entry instanceof Entry.Walls walls) {
            line(out, t, "walls").append(' ').append(walls.walls().size()).append('\n');
            for (Wall wall : walls.walls()) {
                line(out, t, "wall").append(' ').append(metres(wall.x1())).append(' ').append(metres(wall.y1())).append(' ')
                        .append(metres(wall.x2())).append(' ').append(metres(wall.y2()));
                // A wall's material, when it has one, is a fifth field: a recording without is read as before.
                (wall.material().isEmpty() ? out : out.append(' ').append(escape(wall.material()))).append('\n');
            }
        } else if (entry instanceof Entry.Kick kick) {
            words(out, t, "kick", escape(kick.robot()), kick.batteryEmpty() ? "battery" : "absent");
        } else if (entry instanceof Entry.Registered r) {
            words(out, t, "register", escape(r.robot()), escape(r.address()));
        } else if (entry instanceof Entry.Left left) {
            words(out, t, "leave", escape(left.robot()));
        } else if (entry instanceof Entry.Break b) {
            words(out, t, "break", escape(b.first()), escape(b.second()), Strengths.format(b.strength()), metres(b.distance()));
        } else if (entry instanceof Entry.Resume r) {
            words(out, t, "resume", escape(r.first()), escape(r.second()));
        } else if (entry instanceof Entry.Force f) {
            words(out, t, "force", escape(f.first()), escape(f.second()), f.up() ? "up" : "down");
        } else if (entry instanceof Entry.Pin p) {
            words(out, t, "pin", escape(p.first()), escape(p.second()), p.bitsPerSecond() > 0 ? Long.toString(p.bitsPerSecond()) : "-",
                    p.delayMs() >= 0 ? Integer.toString(p.delayMs()) : "-", p.jitterMs() >= 0 ? Integer.toString(p.jitterMs()) : "-");
        } else if (entry instanceof Entry.Release r) {
            words(out, t, "release", escape(r.first()), escape(r.second()));
        } else if (entry instanceof Entry.Replay r) {
            words(out, t, "replay", Strengths.format(Math.round(r.timeSeconds() * 1000) / 1000.0), Strengths.format(r.speed()), r.playing() ? "play" : "pause");
        } else if (entry instanceof Entry.Rate r) {
            words(out, t, "rate", escape(r.from()), escape(r.to()), Long.toString(r.bitsPerSecond()));
        } else if (entry instanceof Entry.Udp u) {
            words(out, t, "udp", escape(u.from()), escape(u.to()), Integer.toString(u.port()), Long.toString(u.datagrams()),
                    Long.toString(u.bytes()),
                    Long.toString(u.droppedBroken()), Long.toString(u.droppedQueue()), Long.toString(u.lost()));
        } else if (entry instanceof Entry.Dropped d) {
            words(out, t, "dropped", Long.toString(d.count()));
        } else if (entry instanceof Entry.End) {
            words(out, t, "end");
        } else {
            throw new IllegalArgumentException("no line for " + entry);
        }
    }

    private static StringBuilder line(StringBuilder out, long millis, String keyword) {
        return out.append(millis).append(' ').append(keyword);
    }

    private static void words(StringBuilder out, long millis, String keyword, String... fields) {
        line(out, millis, keyword);
        for (String field : fields) {
            out.append(' ').append(field);
        }
        out.append('\n');
    }

    /** Metres to the millimetre, trailing zeros dropped: {@code 12.5}, {@code -3}, {@code 0.045}; NaN as {@code -}. */
    static String metres(double value) {
        if (!Double.isFinite(value)) {
            return "-";
        }
        long thousandths = Math.round(value * 1000);
        if (thousandths % 1000 == 0) {
            return Long.toString(thousandths / 1000);
        }
        return Decimals.plain(BigDecimal.valueOf(thousandths, 3));
    }

    /** An obstacle count: a whole number as one, NaN (not counted) as {@code -}. */
    static String count(double value) {
        if (Double.isNaN(value)) {
            return "-";
        }
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? Long.toString((long) value)
                : Decimals.plain(new BigDecimal(value).setScale(3, RoundingMode.HALF_EVEN));
    }

    private static final char[] HEX = "0123456789ABCDEF".toCharArray();

    /** A name or value with '%', whitespace and control characters as {@code %XX} (their UTF-8 bytes); empty as {@code %}. */
    public static String escape(String text) {
        if (text.isEmpty()) {
            return "%";
        }
        if (text.chars().noneMatch(c -> needsEscape((char) c))) {
            return text;
        }
        StringBuilder out = new StringBuilder(text.length() + 8);
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (!needsEscape(c)) {
                out.append(c);
                continue;
            }
            for (byte b : String.valueOf(c).getBytes(StandardCharsets.UTF_8)) {
                out.append('%').append(HEX[(b >> 4) & 0xF]).append(HEX[b & 0xF]);
            }
        }
        return out.toString();
    }

    /** '%', whitespace, a control character (none of them a surrogate: a name's other characters are kept as they are). */
    private static boolean needsEscape(char c) {
        return c == '%' || Character.isWhitespace(c) || Character.isSpaceChar(c) || Character.isISOControl(c);
    }

    /** The text {@link #escape} wrote; @throws IllegalArgumentException for a broken {@code %XX} */
    public static String unescape(String field) {
        if (field.equals("%")) {
            return "";
        }
        if (field.indexOf('%') < 0) {
            return field;
        }
        StringBuilder out = new StringBuilder(field.length());
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        int i = 0;
        while (i < field.length()) {
            if (field.charAt(i) != '%') {
                out.append(field.charAt(i++));
                continue;
            }
            bytes.reset();
            while (i < field.length() && field.charAt(i) == '%') {
                int hi = i + 2 < field.length() ? Character.digit(field.charAt(i + 1), 16) : -1;
                int lo = i + 2 < field.length() ? Character.digit(field.charAt(i + 2), 16) : -1;
                if (hi < 0 || lo < 0) {
                    throw new IllegalArgumentException("a broken %XX in " + shorten(field));
                }
                bytes.write(hi * 16 + lo);
                i += 3;
            }
            out.append(bytes.toString(StandardCharsets.UTF_8));
        }
        return out.toString();
    }

    // ---- reading ----

    /** A line of a recording's body, read: a whole entry, or a part of a poll or of walls. */
    public sealed interface Line {
        long millis();
    }

    /** An entry of one line. */
    public record Whole(Entry entry) implements Line {
        public long millis() {
            return entry.millis();
        }
    }

    /** A poll's first line: how many robot and pair lines follow. */
    public record PollHead(long millis, int robots, int pairs) implements Line {
    }

    public record RobotRow(long millis, ModelPoll.Robot robot) implements Line {
    }

    public record PairRow(long millis, ModelPoll.Pair pair) implements Line {
    }

    /** The first line of a set of walls: how many wall lines follow. */
    public record WallsHead(long millis, int walls) implements Line {
    }

    public record WallRow(long millis, Wall wall) implements Line {
    }

    /** A body line with a keyword this version does not know (skipped, counted). */
    public record Unknown(long millis, String keyword) implements Line {
    }

    /**
     * A body line, read.
     *
     * @throws IllegalArgumentException when it is not {@code MILLIS KEYWORD ...} or a known
     *                                  keyword's fields are wrong; the message says what
     */
    public static Line read(String text) {
        String[] f = split(text);
        if (f.length < 2) {
            throw new IllegalArgumentException("not MILLIS KEYWORD ...: " + shorten(text));
        }
        long t = millis(f[0]);
        return switch (f[1]) {
            case "poll" -> new PollHead(t, size(f, 2, 4), size(f, 3, 4));
            case "robot" -> {
                fields(f, 7);
                String battery = f[6];
                if (!battery.equals("ok") && !battery.equals("empty")) {
                    throw new IllegalArgumentException("a battery is ok or empty: " + shorten(text));
                }
                yield new RobotRow(t, new ModelPoll.Robot(unescape(f[2]),
                        new Position(number(f[3]), number(f[4]), number(f[5])), battery.equals("empty")));
            }
            case "pair" -> {
                fields(f, 7);
                yield new PairRow(t, new ModelPoll.Pair(unescape(f[2]), unescape(f[3]), strength(f[4]),
                        f[5].equals("-") ? Double.NaN : number(f[5]), upDown(f[6])));
            }
            case "walls" -> new WallsHead(t, size(f, 2, 3));
            case "wall" -> {
                fields(f, f.length == 7 ? 7 : 6);
                yield new WallRow(t, new Wall(number(f[2]), number(f[3]), number(f[4]), number(f[5]), f.length == 7 ? unescape(f[6]) : ""));
            }
            case "kick" -> {
                fields(f, 4);
                if (!f[3].equals("battery") && !f[3].equals("absent")) {
                    throw new IllegalArgumentException("a kick is for battery or absent: " + shorten(text));
                }
                yield new Whole(new Entry.Kick(t, unescape(f[2]), f[3].equals("battery")));
            }
            case "register" -> {
                fields(f, 4);
                yield new Whole(new Entry.Registered(t, unescape(f[2]), unescape(f[3])));
            }
            case "leave" -> {
                fields(f, 3);
                yield new Whole(new Entry.Left(t, unescape(f[2])));
            }
            case "break" -> {
                fields(f, 6);
                yield new Whole(new Entry.Break(t, unescape(f[2]), unescape(f[3]), strength(f[4]),
                        f[5].equals("-") ? Double.NaN : number(f[5])));
            }
            case "resume" -> {
                fields(f, 4);
                yield new Whole(new Entry.Resume(t, unescape(f[2]), unescape(f[3])));
            }
            case "force" -> {
                fields(f, 5);
                yield new Whole(new Entry.Force(t, unescape(f[2]), unescape(f[3]), upDown(f[4])));
            }
            case "pin" -> {
                fields(f, 7);
                yield new Whole(new Entry.Pin(t, unescape(f[2]), unescape(f[3]), f[4].equals("-") ? 0 : whole(f[4]),
                        f[5].equals("-") ? -1 : (int) whole(f[5]), f[6].equals("-") ? -1 : (int) whole(f[6])));
            }
            case "release" -> {
                fields(f, 4);
                yield new Whole(new Entry.Release(t, unescape(f[2]), unescape(f[3])));
            }
            case "replay" -> {
                fields(f, 5);
                if (!f[4].equals("play") && !f[4].equals("pause")) {
                    throw new IllegalArgumentException("a replay is play or pause: " + shorten(text));
                }
                yield new Whole(new Entry.Replay(t, number(f[2]), number(f[3]), f[4].equals("play")));
            }
            case "rate" -> {
                fields(f, 5);
                yield new Whole(new Entry.Rate(t, unescape(f[2]), unescape(f[3]), whole(f[4])));
            }
            case "udp" -> {
                if (f.length == 9) { // written before the line said its port (issue 36): FROM TO and the five counts
                    yield new Whole(new Entry.Udp(t, unescape(f[2]), unescape(f[3]), Entry.Udp.NO_PORT, whole(f[4]), whole(f[5]),
                            whole(f[6]), whole(f[7]), whole(f[8])));
                }
                fields(f, 10);
                yield new Whole(new Entry.Udp(t, unescape(f[2]), unescape(f[3]), port(f[4]), whole(f[5]), whole(f[6]), whole(f[7]),
                        whole(f[8]), whole(f[9])));
            }
            case "dropped" -> {
                fields(f, 3);
                yield new Whole(new Entry.Dropped(t, whole(f[2])));
            }
            case "end" -> {
                fields(f, 2);
                yield new Whole(new Entry.End(t));
            }
            default -> new Unknown(t, f[1]);
        };
    }

    /** Splits on single spaces (the writer's separator); a tab or two spaces make an empty field, refused. */
    private static String[] split(String text) {
        List<String> fields = new ArrayList<>(8);
        int start = 0;
        for (int i = 0; i <= text.length(); i++) {
            if (i == text.length() || text.charAt(i) == ' ') {
                if (i == start) {
                    throw new IllegalArgumentException("an empty field (two spaces, or a space at an end): " + shorten(text));
                }
                fields.add(text.substring(start, i));
                start = i + 1;
            }
        }
        return fields.toArray(new String[0]);
    }

    private static void fields(String[] f, int count) {
        if (f.length != count) {
            throw new IllegalArgumentException("a " + f[1] + " line has " + (count - 2) + " fields after its keyword, not "
                    + (f.length - 2));
        }
    }

    private static int size(String[] f, int index, int count) {
        fields(f, count);
        long value = whole(f[index]);
        if (value > 1_000_000) {
            throw new IllegalArgumentException("a " + f[1] + " line of over a million rows: " + f[index]);
        }
        return (int) value;
    }

    /** A fixed port's number, 1 to 65535. */
    private static int port(String text) {
        long value = whole(text);
        if (value < 1 || value > 65535) {
            throw new IllegalArgumentException("not a port number from 1 to 65535: " + text);
        }
        return (int) value;
    }

    static long millis(String text) {
        return whole(text);
    }

    private static long whole(String text) {
        long value = 0;
        if (text.isEmpty() || text.length() > 18) {
            throw new IllegalArgumentException("not a whole number of 0 or more: " + shorten(text));
        }
        for (int i = 0; i < text.length(); i++) {
            int digit = text.charAt(i) - '0';
            if (digit < 0 || digit > 9) {
                throw new IllegalArgumentException("not a whole number of 0 or more: " + shorten(text));
            }
            value = value * 10 + digit;
        }
        return value;
    }

    private static double number(String text) {
        if (!text.isEmpty() && (Character.isDigit(text.charAt(0)) || text.charAt(0) == '-' || text.charAt(0) == '.')) {
            try {
                double value = Double.parseDouble(text);
                if (Double.isFinite(value) && text.chars().allMatch(c -> c == '-' || c == '.' || c == 'e' || c == 'E'
                        || c == '+' || Character.isDigit(c))) {
                    return value;
                }
            } catch (NumberFormatException e) {
                // said below
            }
        }
        throw new IllegalArgumentException("not a number: " + shorten(text));
    }

    /** A strength as {@link Strengths#format} writes it: a number, {@code INF}, {@code -INF} or {@code NaN}. */
    private static double strength(String text) {
        return switch (text) {
            case "INF" -> Double.POSITIVE_INFINITY;
            case "-INF" -> Double.NEGATIVE_INFINITY;
            case "NaN" -> Double.NaN;
            default -> number(text);
        };
    }

    private static boolean upDown(String text) {
        return switch (text) {
            case "up" -> true;
            case "down" -> false;
            default -> throw new IllegalArgumentException("a state is up or down, not " + shorten(text));
        };
    }

    private static String shorten(String text) {
        return text.length() <= 80 ? text : text.substring(0, 77) + "...";
    }
}
