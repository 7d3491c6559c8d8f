package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.LocalTime;
import java.time.ZoneId;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.protocol.Replies;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingReader;
import org.usarsim.wss.world.WorldServer;

/**
 * Issue 17's "faithful": the minute of {@code docs/examples/building.world} with the Obstacle model
 * and its four robots, recorded by the real server; then the recording replayed by another
 * server, with no simulator, to the same four robots. The two CSV event logs hold the same breaks
 * and resumes in the same order, each within one poll interval of its recorded time; every GETSS
 * during the replay equals the recorded strength of the poll the replay was at.
 *
 * <p>The minute runs {@link #FASTER} times faster, so that recording and replay take 30 s each
 * rather than a minute: the world's speeds are multiplied and Scout's battery divided by it, and so
 * is the example's poll interval (1 s): every poll finds the robots where the example's would. (Not
 * faster: the world's clock starts before the recording server does, so its start costs that many
 * times more of the minute. The replay at its own speed: a GETSS is checked against the polls
 * within 0.1 s of the replay's time, which a faster replay would make a race on a loaded machine.)
 */
@Timeout(value = 240, unit = TimeUnit.SECONDS)
@Tag("slow")
class RecordAndReplayTest {

    private static final List<String> ROBOTS = List.of("Operator", "Explorer", "Mapper", "Scout");
    /** How much faster than the example the world runs (and the WSS polls it). */
    private static final int FASTER = 2;
    private static final long POLL_INTERVAL_MS = 1000 / FASTER;
    private static final Pattern LOG_TIME = Pattern.compile("^\\d{4}-\\d\\d-\\d\\d (\\d\\d:\\d\\d:\\d\\d\\.\\d{3}) ");
    private static final Pattern SPEED = Pattern.compile("^path .* speed ([0-9.]+) ");
    private static final Pattern BATTERY = Pattern.compile("^robot .* battery ([0-9.]+)");
    private static final Pattern REPLAY_TIME = Pattern.compile("\\{Time ([0-9.]+)\\}");

    @TempDir
    Path dir;

    private WorldServer world;
    private final List<ServerProcess> servers = new ArrayList<>();

    @AfterEach
    void stop() throws Exception {
        for (ServerProcess server : servers) {
            server.kill();
        }
        if (world != null) {
            world.close();
        }
    }

    /** One break or resume as a CSV event log has it, at ms from its server's start. */
    private record Change(String type, RobotPair pair, long millis) {
    }

    @Test
    void aReplayHasTheRecordedBreaksAndResumesAndStrengths() throws Exception {
        world = WorldServer.start(faster(Path.of("docs/examples/building.world")), InetAddress.getByName("127.0.0.1"), 0);
        Path recording = dir.resolve("building.rec");
        Path recordedLogs = dir.resolve("recorded");
        ServerProcess recorder = start(Map.of("usarsim.port", String.valueOf(world.port()), "usarsim.interval",
                String.valueOf(POLL_INTERVAL_MS), "wss.record", recording.toString(), "wss.eventLogDir", recordedLogs.toString()));
        recorder.awaitLine(text -> text.contains("ObstaclePropagationModel polls the simulator"));
        int port = Integer.parseInt(recorder.awaitListening().group(1));
        runRobots(recorder, port, null);
        // The poll that kicked Scout is written once the poll is whole (its obstacles counted): a stop before would abandon it.
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!Files.readString(recording).contains(" kick Scout battery\n")) {
            assertTrue(System.nanoTime() < deadline, "the poll that kicked Scout was recorded");
            java.util.concurrent.locks.LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(20));
        }
        recorder.sigterm();
        assertEquals(0, recorder.awaitExit());
        Recording recorded = RecordingReader.read(recording);
        assertFalse(recorded.cutShort(), "a clean stop ends the recording");
        // The world's clock ran while the server started: the recording holds most of the minute, a poll each interval.
        assertTrue(recorded.durationMillis() >= 45_000 / FASTER, recorded.durationMillis() + " ms recorded");
        assertTrue(recorded.polls().size() >= recorded.durationMillis() / POLL_INTERVAL_MS - 2,
                recorded.polls().size() + " polls in " + recorded.durationMillis() + " ms");
        // The recording's times count from its start (its header's): the recorded log's times too.
        long recordedStart = LocalTime.ofInstant(Instant.parse(recorded.header().started()), ZoneId.systemDefault()).toNanoOfDay()
                / 1_000_000;

        Path replayedLogs = dir.resolve("replayed");
        world.close();
        world = null; // no simulator from here on
        ServerProcess replayer = start(Map.of("wss.model", "ReplayPropagationModel", "replay.file", recording.toString(),
                "wss.operators", "127.0.0.1", "wss.eventLogDir", replayedLogs.toString()));
        long replayedStart = startedAt(replayer, "replaying");
        port = Integer.parseInt(replayer.awaitListening().group(1));
        int checked = runRobots(replayer, port, recorded);
        replayer.sigterm();
        assertEquals(0, replayer.awaitExit());

        List<Change> before = changes(recordedLogs, recordedStart);
        List<Change> after = changes(replayedLogs, replayedStart);
        assertTrue(before.size() >= 2, "the minute has breaks and resumes: " + before);
        assertEquals(before.stream().map(c -> c.type() + " " + c.pair()).toList(),
                after.stream().map(c -> c.type() + " " + c.pair()).toList(), "the same breaks and resumes in the same order");
        for (int i = 0; i < before.size(); i++) {
            long apart = Math.abs(after.get(i).millis() - before.get(i).millis());
            assertTrue(apart <= POLL_INTERVAL_MS, before.get(i) + " replayed as " + after.get(i) + ": " + apart + " ms apart");
        }
        assertTrue(checked >= 50, checked + " GETSS checked against the recording");
        long worst = 0;
        for (int i = 0; i < before.size(); i++) {
            worst = Math.max(worst, Math.abs(after.get(i).millis() - before.get(i).millis()));
        }
        System.out.printf("RecordAndReplayTest: %d polls recorded, %d breaks and resumes replayed in order (at most %d ms from"
                + " their recorded time), %d GETSS equal to the recorded strength%n", recorded.polls().size(), before.size(), worst,
                checked);
    }

    /** The world file with its robots {@link #FASTER} times faster and the batteries as much shorter, in the test's folder. */
    private Path faster(Path world) throws Exception {
        StringBuilder text = new StringBuilder();
        for (String line : Files.readAllLines(world)) {
            text.append(scaled(scaled(line, SPEED, FASTER), BATTERY, 1.0 / FASTER)).append('\n');
        }
        return Files.writeString(dir.resolve(world.getFileName()), text);
    }

    private static String scaled(String line, Pattern number, double factor) {
        Matcher matcher = number.matcher(line);
        return matcher.find() ? line.substring(0, matcher.start(1)) + Double.parseDouble(matcher.group(1)) * factor
                + line.substring(matcher.end(1)) : line;
    }

    private ServerProcess start(Map<String, String> settings) throws Exception {
        List<String> lines = new ArrayList<>(Files.readAllLines(Path.of("docs/examples/building.properties")));
        lines.add("wss.port = 0");
        lines.add("wss.bindAddress = 127.0.0.1");
        lines.add("wss.eventLog = true");
        settings.forEach((key, value) -> lines.add(key + " = " + value.replace("\\", "\\\\")));
        Path config = Files.write(dir.resolve("wss-" + servers.size() + ".properties"), lines);
        ServerProcess server = ServerProcess.start("--headless", "--config", config.toString());
        servers.add(server);
        return server;
    }

    /** The time of day (ms) of the server's log line that says its model started. */
    private static long startedAt(ServerProcess server, String words) throws InterruptedException {
        String line = server.awaitLine(text -> text.contains(words));
        Matcher matcher = LOG_TIME.matcher(line);
        assertTrue(matcher.find(), line);
        return LocalTime.parse(matcher.group(1)).toNanoOfDay() / 1_000_000;
    }

    /**
     * The four robots register and stay until Scout's battery runs out (at the minute's end: the model kicks it);
     * with {@code recorded}, Operator asks GETSS of the others all along, each between two
     * {@code REPLAY} questions, and each answer must be the recorded strength of a poll the
     * replay was at meanwhile. Returns how many were checked.
     */
    private int runRobots(ServerProcess server, int port, Recording recorded) throws Exception {
        List<TestRobot> robots = new ArrayList<>();
        int checked = 0;
        try (Socket operatorSocket = recorded == null ? null : new Socket("127.0.0.1", port)) {
            for (String name : ROBOTS) {
                TestRobot robot = new TestRobot(port, "127.0.0.1");
                robot.init(name, 5000);
                robots.add(robot);
            }
            TestRobot scout = robots.get(3);
            BufferedReader operatorIn = operatorSocket == null ? null
                    : new BufferedReader(new InputStreamReader(operatorSocket.getInputStream(), StandardCharsets.UTF_8));
            PrintWriter operatorOut = operatorSocket == null ? null
                    : new PrintWriter(operatorSocket.getOutputStream(), true, StandardCharsets.UTF_8);
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(100);
            while (!closedByPeer(scout)) {
                if (System.nanoTime() > deadline) {
                    List<String> out = server.stdoutSoFar();
                    fail("Scout was not kicked at the end of its battery; the server's log ends: "
                            + out.subList(Math.max(0, out.size() - 30), out.size()));
                }
                if (recorded != null) {
                    for (String peer : List.of("Explorer", "Mapper", "Scout")) {
                        double t0 = replayTime(operatorOut, operatorIn);
                        String answer = robots.get(0).ask("GETSS {Robot " + peer + "}");
                        double t1 = replayTime(operatorOut, operatorIn);
                        if (answer.contains("Robot.Does.Not.Exist")) {
                            continue; // Scout, kicked meanwhile
                        }
                        assertRecorded(recorded, peer, answer, t0, t1);
                        checked++;
                    }
                }
            }
        } finally {
            for (TestRobot robot : robots) {
                robot.close();
            }
        }
        return checked;
    }

    private static boolean closedByPeer(TestRobot robot) throws Exception {
        robot.control.setSoTimeout(100);
        try {
            return robot.control.getInputStream().read() < 0;
        } catch (java.net.SocketTimeoutException e) {
            return false;
        } catch (java.io.IOException e) {
            return true;
        }
    }

    private static double replayTime(PrintWriter out, BufferedReader in) throws Exception {
        out.print("REPLAY\r\n");
        out.flush();
        String reply = in.readLine();
        Matcher matcher = REPLAY_TIME.matcher(reply);
        assertTrue(reply.startsWith("REPLAYREPLY {Status OK}") && matcher.find(), reply);
        return Double.parseDouble(matcher.group(1));
    }

    /** The answer is the strength of Operator to the peer in one of the polls the replay was at between t0 and t1 (seconds). */
    private static void assertRecorded(Recording recorded, String peer, String answer, double t0, double t1) {
        // REPLAY says the time to a tenth of a second at least: the polls within that of either end count too.
        int from = Math.max(0, recorded.pollIndexAt((long) Math.floor(t0 * 1000) - 100));
        int to = Math.max(0, recorded.pollIndexAt((long) Math.ceil(t1 * 1000) + 100));
        List<String> possible = new ArrayList<>();
        for (int i = from; i <= to; i++) {
            Entry.Poll poll = recorded.polls().get(i);
            RobotPair pair = RobotPair.of("Operator", peer);
            double strength = poll.pairs().stream().filter(p -> p.first().equals(pair.first()) && p.second().equals(pair.second()))
                    .mapToDouble(ModelPoll.Pair::strength).findFirst().orElse(Double.NaN);
            possible.add(Replies.signal(peer, strength));
        }
        assertTrue(possible.contains(answer), "GETSS " + peer + " at " + t0 + "-" + t1 + " s answered " + answer + "; recorded: "
                + possible);
    }

    /** The OUT_OF_RANGE and IN_RANGE lines of the one CSV event log in {@code logs}, at ms from {@code start} (time of day). */
    private static List<Change> changes(Path logs, long start) throws Exception {
        Path log;
        try (var files = Files.list(logs)) {
            log = files.filter(file -> file.getFileName().toString().startsWith("log-")).findFirst().orElseThrow();
        }
        List<Change> changes = new ArrayList<>();
        for (String line : Files.readAllLines(log)) {
            String[] fields = line.split(",");
            if (fields[0].equals("OUT_OF_RANGE") || fields[0].equals("IN_RANGE")) {
                long millis = LocalTime.parse(fields[1]).toNanoOfDay() / 1_000_000 - start;
                changes.add(new Change(fields[0], RobotPair.of(fields[2], fields[3]), Math.floorMod(millis, 86_400_000L)));
            }
        }
        return changes;
    }
}
