package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
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
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingReader;
import org.usarsim.wss.world.RosbridgeServer;
import org.usarsim.wss.world.WorldServer;

/**
 * A run with positions over rosbridge is recorded as any other (issue 23, item 7), and replays with
 * no rosbridge and no world: the recording holds positions, not where they came from.
 */
@Tag("slow")
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RosbridgeRecordTest {

    /** Runner drives from 10 m to 90 m east of Base and back at 50 m/s; range 55.6 m. */
    private static final String WORLD = """
            robot Base   0,0,0
            robot Runner 10,0,0
            path Runner speed 50 loop 90,0
            """;

    @TempDir
    Path dir;

    private WorldServer world;
    private RosbridgeServer rosbridge;
    private Server server;

    @AfterEach
    void stop() {
        if (server != null) {
            server.close();
        }
        if (rosbridge != null) {
            rosbridge.close();
        }
        if (world != null) {
            world.close();
        }
    }

    private Server start(Properties properties, List<String> seen) throws Exception {
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        properties.setProperty("wss.port", "0");
        ConfigFile config = ConfigFile.of(properties, "test");
        Server started = Server.create(config.hubConfig(), config.catalog().provider(config.modelName()), config.modelValues(), null,
                config.record().orElse(null));
        started.hub().addListener(new WssEventListener() {
            @Override
            public void connectionOutOfRange(String from, String to, double strength, double distance) {
                seen.add("break");
            }

            @Override
            public void connectionInRange(String from, String to) {
                seen.add("resume");
            }
        });
        started.start();
        return started;
    }

    @Test
    void aRunOverRosbridgeIsRecordedAndReplaysWithoutIt() throws Exception {
        world = WorldServer.start(Files.writeString(dir.resolve("run.world"), WORLD), InetAddress.getByName("127.0.0.1"), 0);
        rosbridge = RosbridgeServer.start(world, InetAddress.getByName("127.0.0.1"), 0);
        Path file = dir.resolve("run.rec");
        Properties recording = new Properties();
        recording.setProperty("wss.model", "DistanceOnlyPropagationModel");
        recording.setProperty("wss.record", file.toString());
        recording.setProperty("positions", "rosbridge");
        recording.setProperty("rosbridge.url", "ws://127.0.0.1:" + rosbridge.port());
        recording.setProperty("positions.interval", "100");
        recording.setProperty("distance.n", "3");
        List<String> seen = new CopyOnWriteArrayList<>();
        server = start(recording, seen);
        int port = server.hub().controlPort();
        try (TestRobot base = new TestRobot(port, "127.0.0.1"); TestRobot runner = new TestRobot(port, "127.0.0.1")) {
            base.init("Base");
            runner.init("Runner");
            Wait.until("Runner drives out of range and back", () -> seen.contains("break") && seen.lastIndexOf("resume") > seen.indexOf("break"));
        }
        server.close();
        server = null;
        rosbridge.close();
        rosbridge = null;
        world.close();
        world = null;

        Recording recorded = RecordingReader.read(file);
        assertFalse(recorded.cutShort());
        assertEquals("rosbridge", recorded.header().settings().get("positions"));
        List<Entry.Poll> polls = recorded.polls();
        assertTrue(polls.stream().map(p -> p.robots().stream().filter(r -> r.name().equals("Runner")).findFirst()
                .map(r -> r.position().x()).orElse(-1.0)).distinct().count() > 5, "Runner moves from poll to poll");
        assertTrue(recorded.events().stream().anyMatch(e -> e instanceof Entry.Break), "a break recorded");
        ModelPoll.Pair pair = polls.get(polls.size() - 1).pairs().get(0);
        assertEquals(List.of("Base", "Runner"), List.of(pair.first(), pair.second()));

        Properties replay = new Properties();
        replay.setProperty("wss.model", "ReplayPropagationModel");
        replay.setProperty("replay.file", file.toString());
        List<String> replayed = new CopyOnWriteArrayList<>();
        server = start(replay, replayed);
        port = server.hub().controlPort();
        try (TestRobot base = new TestRobot(port, "127.0.0.1"); TestRobot runner = new TestRobot(port, "127.0.0.1")) {
            base.init("Base");
            runner.init("Runner");
            Wait.until("the replay breaks the pair as recorded, with no rosbridge", () -> replayed.contains("break"));
        }
    }
}
