package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.app.MainRun;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.EntryLines;
import org.usarsim.wss.recording.Header;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingReader;
import org.usarsim.wss.recording.WorldExport;

/**
 * {@code --export-world}: a recording written with {@link EntryLines}, read back, exported, and the
 * world file parsed as the world server parses it: at every recorded time every robot is where it
 * was recorded (within 1 mm), its battery empty from when it was recorded empty, and the walls are
 * the last recorded.
 */
class WorldExportTest {

    private static final double MM = 0.001 + 1e-9;

    @TempDir
    Path dir;

    /** A 20 s run polled every 200 ms: Alpha drives a straight line then turns, Bravo stands still and runs out, Circler circles from 3 s on. */
    private Path recording(boolean ended) throws Exception {
        StringBuilder text = new StringBuilder();
        EntryLines.header(text, new Header(EntryLines.VERSION, "0.1.0-TEST", "2026-11-25T14:30:00.123Z", "ObstaclePropagationModel",
                Map.of("usarsim.interval", "200")));
        EntryLines.write(text, new Entry.Registered(0, "Alpha", "127.0.0.1"));
        EntryLines.write(text, new Entry.Walls(150, List.of(new org.usarsim.wss.model.Wall(0, 0, 1, 0))));
        for (long t = 200; t <= 20_000; t += 200) {
            double s = t / 1000.0;
            List<ModelPoll.Robot> robots = new ArrayList<>();
            robots.add(new ModelPoll.Robot("Alpha", s <= 10 ? new Position(s * 1.5, -2, 0.45) : new Position(15, -2 + (s - 10) * 0.5, 0.45), false));
            robots.add(new ModelPoll.Robot("Bravo", new Position(12.345, 0, 0), t >= 12_000));
            if (t >= 3000) {
                robots.add(new ModelPoll.Robot("Circler", new Position(round(5 * Math.cos(s)), round(5 * Math.sin(s)), 0), false));
                robots.add(new ModelPoll.Robot("two words", new Position(1, 1, 1), false));
            }
            EntryLines.write(text, new Entry.Poll(t, robots, List.of(new ModelPoll.Pair("Alpha", "Bravo", -60, 1, true))));
            if (t == 5000) {
                EntryLines.write(text, new Entry.Walls(t, List.of(new org.usarsim.wss.model.Wall(10, 4, 10, 14),
                        new org.usarsim.wss.model.Wall(-1.5, 2.25, 80, 2.25, "brick"), new org.usarsim.wss.model.Wall(3, 3, 3, 3))));
            }
        }
        if (ended) {
            EntryLines.write(text, new Entry.End(20_001));
        }
        Path file = dir.resolve(ended ? "run.rec" : "crashed.rec");
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return file;
    }

    /** To the millimetre, as a recording writes positions. */
    private static double round(double metres) {
        return Math.round(metres * 1000) / 1000.0;
    }

    @Test
    void theExportedWorldsRobotsAreWhereTheRecordingHadThemAtEveryRecordedTime() throws Exception {
        Recording recording = RecordingReader.read(recording(true));
        String text = WorldExport.worldFile(recording, "run.rec");
        World world = WorldFile.parse("exported.world", text.lines().toList());

        assertEquals(3, world.robotCount(), "Alpha, Bravo, Circler; not the name with a space:\n" + text);
        int checked = 0;
        for (Entry.Poll poll : recording.polls()) {
            Snapshot snapshot = world.at(poll.millis() / 1000.0);
            for (ModelPoll.Robot recorded : poll.robots()) {
                if (recorded.name().equals("two words")) {
                    continue;
                }
                RobotAt robot = snapshot.robot(recorded.name()).orElseThrow();
                Position p = recorded.position();
                double off = robot.position().distanceTo(new Point(p.x(), p.y(), p.z()));
                assertTrue(off <= MM, recorded.name() + " at " + poll.millis() + " ms is " + off + " m off: " + robot.position());
                assertEquals(recorded.batteryEmpty(), robot.batteryEmpty(), recorded.name() + "'s battery at " + poll.millis() + " ms");
                checked++;
            }
        }
        assertEquals(100 + 100 + 86, checked);
        assertEquals(new Point(0.3, -2, 0.45), world.at(0).robot("Alpha").orElseThrow().position(), "before its first poll: its first position");
        assertEquals(new Point(15, 3, 0.45), world.at(500).robot("Alpha").orElseThrow().position(), "after its last: it stays");
        assertEquals(List.of(new Wall(10, 4, 10, 14), new Wall(-1.5, 2.25, 80, 2.25, "brick")), world.at(0).walls(),
                "the last walls recorded with their materials, the one of length 0 left out");
    }

    @Test
    void onlyThePointsNeededAreWritten() throws Exception {
        String text = WorldExport.worldFile(RecordingReader.read(recording(true)), "run.rec");
        List<String> lines = text.lines().toList();
        assertEquals(List.of("at Alpha 0.2 0.3,-2,0.45", "at Alpha 10 15,-2,0.45", "at Alpha 20 15,3,0.45"),
                lines.stream().filter(line -> line.startsWith("at Alpha ")).toList(), "a straight line, a turn: three points\n" + text);
        assertEquals(List.of("at Bravo 0.2 12.345,0,0", "at Bravo 20 12.345,0,0"),
                lines.stream().filter(line -> line.startsWith("at Bravo ")).toList(), "standing still: two points");
        assertTrue(lines.contains("robot Bravo 12.345,0,0 battery 12"), text);
        assertTrue(lines.contains("robot Alpha 0.3,-2,0.45"), text);
        long circler = lines.stream().filter(line -> line.startsWith("at Circler ")).count();
        assertEquals(86, circler, "a circle: every point needed");
        assertTrue(lines.get(0).startsWith("# A world exported from the WSS recording run.rec"), lines.get(0));
        assertTrue(text.contains("# left out: the robot two%20words,"), text);
        assertTrue(lines.contains("wall -1.5,2.25 80,2.25 brick"), text);
        assertFalse(text.contains("cut short"), text);
    }

    @Test
    void theCommandLineWritesItToStandardOutputOrAFileAndRefusesABadRecording() throws Exception {
        Path rec = recording(true);
        MainRun run = MainRun.of("--export-world", rec.toString());
        assertEquals(0, run.exitCode(), run.stderr());
        assertEquals("", run.stderr());
        String expected = WorldExport.worldFile(RecordingReader.read(rec), "run.rec");
        assertEquals(expected.lines().toList(), run.stdoutLines());

        Path out = dir.resolve("run.world");
        run = MainRun.of("--export-world", rec.toString(), "--out", out.toString());
        assertEquals(0, run.exitCode(), run.stderr());
        assertEquals(List.of(), run.stdoutLines());
        assertEquals(expected, Files.readString(out));
        assertEquals(3, WorldFile.read(out).robotCount());

        Path crashed = recording(false);
        run = MainRun.of("--export-world", crashed.toString());
        assertEquals(0, run.exitCode(), run.stderr());
        assertEquals("wss: warning: " + crashed + " was cut short (no end line): exported up to its last whole line\n",
                run.stderr().replace("\r\n", "\n"));
        assertTrue(run.stdoutLines().contains("# The recording was cut short (no end line): exported up to its last whole line."));

        Path notOne = dir.resolve("not.rec");
        Files.writeString(notOne, "robot A 0,0,0\n");
        run = MainRun.of("--export-world", notOne.toString());
        assertEquals(2, run.exitCode());
        assertEquals(List.of(), run.stdoutLines());
        assertEquals(List.of("wss: " + notOne + " is not a WSS recording (its first line is not WSS-RECORDING 1)"), run.stderr().lines().toList());

        run = MainRun.of("--export-world", dir.resolve("absent.rec").toString());
        assertEquals(2, run.exitCode());
        assertEquals(List.of("wss: " + dir.resolve("absent.rec") + ": no such file"), run.stderr().lines().toList());

        // Issue 36, item 12: a header only (a run of a model without a simulator) is refused as the replay refuses it.
        StringBuilder headerOnly = new StringBuilder();
        EntryLines.header(headerOnly, new Header(EntryLines.VERSION, "0.1.0-TEST", "2026-11-25T14:30:00.123Z", "NoopPropagationModel",
                Map.of()));
        EntryLines.write(headerOnly, new Entry.End(14));
        Path noPoll = Files.writeString(dir.resolve("nopoll.rec"), headerOnly, StandardCharsets.UTF_8);
        run = MainRun.of("--export-world", noPoll.toString(), "--out", dir.resolve("nopoll.world").toString());
        assertEquals(2, run.exitCode(), "bad input");
        assertEquals(List.of("wss: " + noPoll + " holds no poll (recorded with NoopPropagationModel): nothing to replay or export;"
                + " a recording of a simulator model has one per poll interval"), run.stderr().lines().toList());
        assertFalse(Files.exists(dir.resolve("nopoll.world")), "no world written");

        run = MainRun.of("--out", out.toString());
        assertEquals(2, run.exitCode());
        assertTrue(run.stderr().startsWith("wss: --out is where --export-world writes"), run.stderr());
        run = MainRun.of("--export-world", rec.toString(), "--headless");
        assertEquals(2, run.exitCode());
        run = MainRun.of("--export-world");
        assertEquals(2, run.exitCode());
        assertTrue(run.stderr().startsWith("wss: --export-world needs a file"), run.stderr());
        run = MainRun.of("--export-world", rec.toString(), "--out", dir.resolve("no/such/dir/x.world").toString());
        assertEquals(2, run.exitCode());
        assertEquals("wss: cannot write the world file " + dir.resolve("no/such/dir/x.world") + ": its folder "
                + dir.resolve("no/such/dir").toAbsolutePath() + " does not exist", run.stderr().strip(), "one clear line (issue 26, item 7)");

        run = MainRun.of("--help");
        assertTrue(run.stdoutLines().stream().anyMatch(line -> line.startsWith("  --export-world RUN.rec")), "--help lists it");
    }
}
