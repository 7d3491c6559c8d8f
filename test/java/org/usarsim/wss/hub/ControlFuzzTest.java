package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Fuzzed control lines over real sockets to a real hub: random bytes and mutations of valid
 * commands, written in random pieces on 8 connections at once. Every non-blank line gets exactly
 * one reply, none is an internal error, and each session answers a valid command rightly
 * afterwards. Seeded: the seed is in every failure message, and {@code -Dwss.fuzz.seed=N} replays
 * a run ({@code -Dwss.fuzz.lines=N} sets the number of lines, 100,000 by default).
 */
@Tag("slow")
class ControlFuzzTest {

    private static final int CONNECTIONS = 8;
    private static final String[] REPLY_STARTS = {"ERROR {Reason ", "INITREPLY {Status OK}", "SS {Robot ", "DNSREPLY {Robot ",
        "REVERSEDNSREPLY {Port "};
    private static final String[] NUMBERS = {"0", "-1", "70000", "5000", "5001", "65535", "65536", "2147483647",
        "2147483648", "-2147483649", "99999999999999999999", "+5000", "0005000", "", "5000,0", "1e3", "0x10", "５０００"};
    private static final String[] ODD = {"\t", "\u000B", "\f", "\u001C", "\u001D", "\u001E", "\u001F", "\u0000", "\u0001",
        "\u007F", "é", "機", "\uD83E\uDD16", "\u00A0", "\u2028", "{", "}", "{}", "{ }", " ", "  ", ",", "}{"};

    @Test
    void everyNonBlankLineGetsExactlyOneReplyAndTheSessionStaysUsable() throws Exception {
        long seed = Long.getLong("wss.fuzz.seed", new Random().nextLong());
        int totalLines = Integer.getInteger("wss.fuzz.lines", 100_000);
        String replay = " (seed " + seed + "; replay with -Dwss.fuzz.seed=" + seed + ")";
        ExecutorService threads = Executors.newFixedThreadPool(2 * CONNECTIONS);
        try (TestHub server = new TestHub()) {
            List<TestRobot> robots = new ArrayList<>();
            List<Future<List<String>>> replies = new ArrayList<>();
            List<List<byte[]>> sent = new ArrayList<>();
            for (int c = 0; c < CONNECTIONS; c++) {
                Random random = new Random(seed + c);
                List<byte[]> lines = lines(random, c, totalLines / CONNECTIONS);
                TestRobot robot = server.robot();
                robots.add(robot);
                sent.add(lines);
                int expected = (int) lines.stream().filter(line -> !blank(line)).count();
                replies.add(threads.submit(() -> readReplies(robot.control.getInputStream(), expected)));
                threads.submit(() -> {
                    writeInPieces(robot.control.getOutputStream(), lines, random);
                    return null;
                });
            }
            long started = System.nanoTime();
            int initsOk = 0;
            for (int c = 0; c < CONNECTIONS; c++) {
                List<String> got;
                try {
                    got = replies.get(c).get(60, TimeUnit.SECONDS);
                } catch (TimeoutException e) {
                    throw new AssertionError("connection " + c + ": not every reply came within 60 s" + replay, e);
                } catch (ExecutionException e) {
                    throw new AssertionError("connection " + c + ": " + e.getCause().getMessage() + replay, e.getCause());
                }
                List<byte[]> nonBlank = sent.get(c).stream().filter(line -> !blank(line)).toList();
                int registered = 0;
                for (int i = 0; i < got.size(); i++) {
                    String reply = got.get(i);
                    byte[] line = nonBlank.get(i);
                    int connection = c;
                    assertTrue(Arrays.stream(REPLY_STARTS).anyMatch(reply::startsWith) && reply.endsWith("}"),
                            () -> "connection " + connection + ", line '" + show(line) + "': odd reply '" + reply + "'" + replay);
                    assertTrue(!reply.contains("Server.Internal.Error"),
                            () -> "connection " + connection + ", line '" + show(line) + "': " + reply + replay);
                    if (reply.equals("INITREPLY {Status OK}")) {
                        registered++;
                    }
                }
                assertTrue(registered <= 1, "connection " + c + " registered " + registered + " times" + replay);
                initsOk += registered;
                TestRobot robot = robots.get(c);
                assertEquals(registered == 1 ? "ERROR {Reason Method.Unknown.Or.Can.INIT.only.once}" : "INITREPLY {Status OK}",
                        robot.ask("INIT {Robot Final" + c + "} {Port 5000}"), "connection " + c + " after the fuzz" + replay);
            }
            try (TestRobot checker = server.robot()) {
                checker.init("Checker", 6000);
                for (int c = 0; c < CONNECTIONS; c++) {
                    TestRobot robot = robots.get(c);
                    assertEquals("SS {Robot Checker} {Strength 0}", robot.ask("GETSS {Robot Checker}"), "connection " + c + replay);
                    robot.dns("Checker", 6000);
                }
            }
            System.out.println("control fuzz: " + totalLines + " lines on " + CONNECTIONS + " connections, "
                    + initsOk + " of them registered by a fuzzed INIT, " + (System.nanoTime() - started) / 1_000_000 + " ms, seed " + seed);
            for (TestRobot robot : robots) {
                robot.close();
            }
        } finally {
            threads.shutdownNow();
        }
    }

    /** Empty or spaces only, once the line end is taken off: the lines that get no reply. */
    private static boolean blank(byte[] line) {
        int end = line.length - (line.length >= 2 && line[line.length - 2] == '\r' ? 2 : 1);
        for (int i = 0; i < end; i++) {
            if (line[i] != ' ') {
                return false;
            }
        }
        return true;
    }

    /** Lines with their line end (LF or CR LF); no LF nor CR inside a line. */
    private static List<byte[]> lines(Random random, int connection, int count) {
        List<byte[]> lines = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            byte[] body;
            int kind = random.nextInt(100);
            if (kind < 30) {
                body = randomBytes(random, random.nextInt(80));
            } else if (kind < 95) {
                body = mutated(random, connection).getBytes(StandardCharsets.UTF_8);
            } else if (kind < 98) {
                body = " ".repeat(random.nextInt(4)).getBytes(StandardCharsets.US_ASCII);
            } else if (random.nextInt(40) == 0) {
                body = randomBytes(random, 65_530 + random.nextInt(5_000)); // around the 64 KiB limit
            } else {
                body = valid(random, connection).getBytes(StandardCharsets.UTF_8);
            }
            byte[] end = random.nextBoolean() ? new byte[] {'\n'} : new byte[] {'\r', '\n'};
            byte[] line = Arrays.copyOf(body, body.length + end.length);
            System.arraycopy(end, 0, line, body.length, end.length);
            lines.add(line);
        }
        return lines;
    }

    private static byte[] randomBytes(Random random, int length) {
        byte[] bytes = new byte[length];
        random.nextBytes(bytes);
        for (int i = 0; i < length; i++) {
            if (bytes[i] == '\n' || bytes[i] == '\r') {
                bytes[i] = ' ';
            }
        }
        return bytes;
    }

    /** A valid command of this connection: names are the connection's own, so INITs of two connections never clash. */
    private static String valid(Random random, int connection) {
        String name = "c" + connection + "n" + random.nextInt(3);
        String other = "c" + random.nextInt(CONNECTIONS) + "n" + random.nextInt(3);
        String port = NUMBERS[random.nextInt(NUMBERS.length)];
        switch (random.nextInt(5)) {
            case 0:
                return "INIT {Robot " + name + "} {Port " + port + "}";
            case 1:
                return "GETSS {Robot " + other + "}";
            case 2:
                return "DNS {Robot " + other + "} {Port " + port + "}";
            case 3:
                return "DNS {Robot " + other + "}";
            default:
                return "REVERSEDNS {Port " + port + "}";
        }
    }

    /** A valid command with one to three mutations. */
    private static String mutated(Random random, int connection) {
        StringBuilder line = new StringBuilder(valid(random, connection));
        for (int m = 1 + random.nextInt(3); m > 0; m--) {
            int at = random.nextInt(line.length() + 1);
            switch (random.nextInt(9)) {
                case 0 -> line.insert(at, ODD[random.nextInt(ODD.length)]);
                case 1 -> line.insert(at, NUMBERS[random.nextInt(NUMBERS.length)]);
                case 2 -> {
                    if (at < line.length()) {
                        line.deleteCharAt(at);
                    }
                }
                case 3 -> line.setLength(at); // cut
                case 4 -> dropOrDuplicateSegment(line, random);
                case 5 -> replaceAll(line, random.nextBoolean() ? "{" : "}", "");
                case 6 -> line.replace(0, line.length(), random.nextBoolean() ? line.toString().toLowerCase() : line.toString().toUpperCase());
                case 7 -> line.insert(at, "9".repeat(1 + random.nextInt(30)));
                default -> line.insert(at, ODD[random.nextInt(ODD.length)].repeat(1 + random.nextInt(5)));
            }
        }
        return line.toString();
    }

    private static void dropOrDuplicateSegment(StringBuilder line, Random random) {
        int open = line.indexOf("{", random.nextInt(line.length() + 1));
        int close = open < 0 ? -1 : line.indexOf("}", open);
        if (close < 0) {
            return;
        }
        String segment = line.substring(open, close + 1);
        if (random.nextBoolean()) {
            line.delete(open, close + 1);
        } else {
            line.insert(close + 1, " " + segment);
        }
    }

    private static void replaceAll(StringBuilder line, String what, String by) {
        String replaced = line.toString().replace(what, by);
        line.replace(0, line.length(), replaced);
    }

    /** The lines in one stream, cut into random pieces regardless of line ends, each written and flushed. */
    private static void writeInPieces(OutputStream out, List<byte[]> lines, Random random) throws IOException {
        ByteArrayOutputStream all = new ByteArrayOutputStream();
        for (byte[] line : lines) {
            all.write(line);
        }
        byte[] bytes = all.toByteArray();
        int offset = 0;
        while (offset < bytes.length) {
            int piece = Math.min(bytes.length - offset, 1 + random.nextInt(random.nextBoolean() ? 16 : 8192));
            out.write(bytes, offset, piece);
            out.flush();
            offset += piece;
        }
    }

    /** Reads replies (each ending in CR LF, returned without it) until {@code count} have come. */
    private static List<String> readReplies(InputStream in, int count) throws IOException {
        List<String> replies = new ArrayList<>(count);
        ByteArrayOutputStream reply = new ByteArrayOutputStream();
        byte[] buffer = new byte[64 * 1024];
        while (replies.size() < count) {
            int read;
            try {
                read = in.read(buffer);
            } catch (SocketTimeoutException e) {
                throw new IOException("after " + replies.size() + " of " + count + " replies, nothing more came", e);
            }
            if (read < 0) {
                throw new IOException("the server closed the connection after " + replies.size() + " of " + count + " replies");
            }
            for (int i = 0; i < read; i++) {
                reply.write(buffer[i]);
                if (buffer[i] == '\n') {
                    String text = reply.toString(StandardCharsets.UTF_8);
                    if (!text.endsWith("\r\n")) {
                        fail("a reply not ending in CR LF: '" + text + "'");
                    }
                    replies.add(text.substring(0, text.length() - 2));
                    reply.reset();
                }
            }
        }
        if (reply.size() > 0) {
            fail("more than " + count + " replies: '" + reply.toString(StandardCharsets.UTF_8) + "'");
        }
        return replies;
    }

    /** A line as a printable string: control characters and non-ASCII bytes escaped. */
    private static String show(byte[] line) {
        StringBuilder text = new StringBuilder();
        for (byte b : line) {
            int c = b & 0xFF;
            text.append(c >= 0x20 && c < 0x7F ? String.valueOf((char) c) : String.format("\\x%02x", c));
        }
        return text.length() > 300 ? text.substring(0, 300) + "... (" + line.length + " bytes)" : text.toString();
    }
}
