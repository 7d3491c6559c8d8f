package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Properties;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingReader;
import org.usarsim.wss.world.WorldServer;

/**
 * A run recorded for real, as headless runs it (wss.record): our world server, the Obstacle model
 * polling it every 100 ms, robots registering with INIT over the control port, a robot driving
 * out of range behind a wall and back, one the world does not know kicked; then the file read back.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class RecordRunTest {

    /** Runner drives from 10 m to 90 m east of Base and back at 50 m/s (a lap in 3.2 s), through a wall at 40 m. */
    private static final String WORLD = """
            robot Base   0,0,0
            robot Runner 10,0,0.5
            path Runner speed 50 loop 90,0
            wall 40,-5 40,5
            """;

    @TempDir
    Path dir;

    private WorldServer world;
    private Server server;

    @AfterEach
    void stop() {
        if (server != null) {
            server.close();
        }
        if (world != null) {
            world.close();
        }
    }

    @Test
    void aRunOfTheObstacleModelIsRecordedWithItsPollsBreaksResumesKicksAndWalls() throws Exception {
        int worldPort = freePort();
        world = WorldServer.start(Files.writeString(dir.resolve("test.world"), WORLD), InetAddress.getByName("127.0.0.1"), worldPort);
        Path file = dir.resolve("run.rec");
        Properties properties = new Properties();
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        properties.setProperty("wss.port", "0");
        properties.setProperty("wss.model", "ObstaclePropagationModel");
        properties.setProperty("wss.record", file.toString());
        properties.setProperty("usarsim.port", String.valueOf(worldPort));
        properties.setProperty("usarsim.interval", "100");
        properties.setProperty("distance.n", "3"); // a range of 55.6 m in the open, about 40 m through the wall
        ConfigFile config = ConfigFile.of(properties, "test");
        server = Server.create(config.hubConfig(), config.catalog().provider(config.modelName()), config.modelValues(), null,
                config.record().orElseThrow());
        List<String> seen = new CopyOnWriteArrayList<>();
        server.hub().addListener(new WssEventListener() {
            @Override
            public void connectionOutOfRange(String from, String to, double strength, double distance) {
                seen.add("break");
            }

            @Override
            public void connectionInRange(String from, String to) {
                seen.add("resume");
            }

            @Override
            public void robotDeregistered(String robot) {
                seen.add("left " + robot);
            }
        });
        server.start();
        assertEquals(file, server.recording());
        int port = server.hub().controlPort();
        try (TestRobot base = new TestRobot(port, "127.0.0.1"); TestRobot runner = new TestRobot(port, "127.0.0.1");
                TestRobot ghost = new TestRobot(port, "127.0.0.1")) {
            base.init("Base");
            runner.init("Runner");
            ghost.init("Ghost");
            Wait.until("Runner drives out of range", () -> seen.contains("break"));
            Wait.until("Runner comes back", () -> seen.contains("resume"));
            Wait.until("Ghost is kicked", () -> seen.contains("left Ghost"));
        }
        server.close();
        server = null;

        Recording recording = RecordingReader.read(file);
        assertFalse(recording.cutShort(), "it ends with end");
        assertEquals(0, recording.unknownLines() + recording.unreadableLines(), String.valueOf(recording.firstProblem()));
        assertEquals("ObstaclePropagationModel", recording.header().model());
        assertEquals("100", recording.header().settings().get("positions.interval"), "given under its old name, recorded under its key");
        assertEquals("3", recording.header().settings().get("distance.n"));
        assertEquals("off", recording.header().settings().get("wss.shaping"));

        List<Entry> events = recording.events();
        List<String> registered = events.stream().filter(e -> e instanceof Entry.Registered)
                .map(e -> ((Entry.Registered) e).robot() + " " + ((Entry.Registered) e).address()).toList();
        assertEquals(List.of("Base 127.0.0.1", "Runner 127.0.0.1", "Ghost 127.0.0.1"), registered);
        assertTrue(events.contains(new Entry.Kick(kickTime(events), "Ghost", false)), events.toString());
        assertTrue(events.stream().anyMatch(e -> e instanceof Entry.Left left && left.robot().equals("Ghost")));
        assertTrue(events.get(events.size() - 1) instanceof Entry.End, "the last entry is end");

        List<Entry.Break> breaks = events.stream().filter(e -> e instanceof Entry.Break).map(e -> (Entry.Break) e).toList();
        List<Entry.Resume> resumes = events.stream().filter(e -> e instanceof Entry.Resume).map(e -> (Entry.Resume) e).toList();
        assertFalse(breaks.isEmpty());
        assertFalse(resumes.isEmpty());
        Entry.Break broke = breaks.get(0);
        assertEquals(List.of("Base", "Runner"), List.of(broke.first(), broke.second()));
        assertTrue(broke.distance() > 30 && broke.distance() < 90, "out of range at " + broke.distance() + " m");
        // Each break and resume follows the poll that decided it, whose pair says so.
        for (Entry.Break b : breaks) {
            assertEquals(false, pairAt(recording, b.millis()).live(), "the poll before the break at " + b.millis());
            assertEquals(b.strength(), pairAt(recording, b.millis()).strength(), 1e-3);
        }
        for (Entry.Resume r : resumes) {
            assertEquals(true, pairAt(recording, r.millis()).live(), "the poll before the resume at " + r.millis());
        }

        List<Entry.Poll> polls = recording.polls();
        assertTrue(polls.size() >= 10, polls.size() + " polls");
        for (int i = 1; i < polls.size(); i++) {
            long gap = polls.get(i).millis() - polls.get(i - 1).millis();
            assertTrue(gap >= 0 && gap < 2000, "polls " + gap + " ms apart");
        }
        double meanGap = (polls.get(polls.size() - 1).millis() - polls.get(0).millis()) / (double) (polls.size() - 1);
        assertTrue(meanGap > 50 && meanGap < 500, "polls " + meanGap + " ms apart on average, polled every 100 ms");
        Entry.Poll last = polls.get(polls.size() - 1);
        ModelPoll.Robot base = last.robots().stream().filter(r -> r.name().equals("Base")).findFirst().orElseThrow();
        assertEquals(0, base.position().x());
        assertEquals(0, base.position().y());
        ModelPoll.Robot runner = last.robots().stream().filter(r -> r.name().equals("Runner")).findFirst().orElseThrow();
        assertTrue(runner.position().x() >= 10 && runner.position().x() <= 90, "Runner at " + runner.position());
        assertEquals(0.5, runner.position().z());
        assertTrue(polls.stream().map(p -> p.robots().stream().filter(r -> r.name().equals("Runner")).findFirst().orElseThrow()
                .position().x()).distinct().count() > 5, "Runner moves from poll to poll");
        ModelPoll.Pair pair = last.pairs().get(0);
        assertEquals(List.of("Base", "Runner"), List.of(pair.first(), pair.second()));
        assertTrue(polls.stream().anyMatch(p -> p.pairs().size() == 1 && p.pairs().get(0).obstacles() == 1),
                "the wall is counted between them");
        assertEquals(List.of(new Wall(40, -5, 40, 5)), recording.wallsAt(last.millis()));
        assertEquals(1, recording.walls().size(), "the walls are written once");
    }

    /** A port nothing listens on now (where the world server starts). */
    private static int freePort() throws java.io.IOException {
        try (ServerSocket free = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return free.getLocalPort();
        }
    }

    private static long kickTime(List<Entry> events) {
        return events.stream().filter(e -> e instanceof Entry.Kick).findFirst().orElseThrow().millis();
    }

    /** Base and Runner as the last poll at or before {@code millis} had them. */
    private static ModelPoll.Pair pairAt(Recording recording, long millis) {
        Entry.Poll poll = recording.polls().get(recording.pollIndexAt(millis));
        return poll.pairs().stream().filter(p -> p.first().equals("Base") && p.second().equals("Runner")).findFirst().orElseThrow();
    }
}
