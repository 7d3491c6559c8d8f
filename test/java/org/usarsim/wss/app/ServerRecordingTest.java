package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.logging.Level;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.EntryLines;
import org.usarsim.wss.recording.Header;
import org.usarsim.wss.recording.Recorder;
import org.usarsim.wss.recording.RecordingReader;

/** Issue 36, items 9 and 11: a run's recording as the Server starts it (headless and the window's Start alike). */
class ServerRecordingTest {

    @TempDir
    Path dir;

    private static Properties properties(String port, Path record) {
        Properties properties = new Properties();
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        properties.setProperty("wss.port", port);
        properties.setProperty("wss.record", record.toString());
        return properties;
    }

    private static Server server(Properties properties) throws Exception {
        ConfigFile config = ConfigFile.of(properties, "test");
        return Server.create(config.hubConfig(), config.catalog().provider(config.modelName()), config.modelValues(), null,
                config.record().orElseThrow());
    }

    @Test
    void aStartThatFailsLeavesNoRecordingAndNeverSaysItRecords() throws Exception {
        Path file = dir.resolve("run.rec");
        try (ServerSocket taken = new ServerSocket(); LogCapture log = LogCapture.of(Recorder.class.getName(), Level.INFO)) {
            taken.bind(new InetSocketAddress(InetAddress.getByName("127.0.0.1"), 0));
            Server server = server(properties(String.valueOf(taken.getLocalPort()), file));
            assertThrows(Server.StartFailure.class, server::start);
            assertFalse(Files.exists(file), "a run that did not start is not recorded");
            assertEquals(List.of(), log.messages(Level.INFO));
        }
    }

    /** The case: Record ticked, the replay refusing a recording without polls. */
    @Test
    void aReplayThatRefusesItsRecordingRecordsNothing() throws Exception {
        StringBuilder text = new StringBuilder();
        EntryLines.header(text, new Header(EntryLines.VERSION, "0.1.0-TEST", "2026-11-28T06:55:00.000Z", "NoopPropagationModel", Map.of()));
        EntryLines.write(text, new Entry.End(14));
        Path replayed = Files.writeString(dir.resolve("nopolls.rec"), text, StandardCharsets.UTF_8);
        Path file = dir.resolve("again.rec");
        Properties properties = properties("0", file);
        properties.setProperty("wss.model", "ReplayPropagationModel");
        properties.setProperty("replay.file", replayed.toString());
        try (LogCapture log = LogCapture.of(Recorder.class.getName(), Level.INFO)) {
            Server server = server(properties);
            Server.StartFailure failure = assertThrows(Server.StartFailure.class, server::start);
            assertTrue(failure.badInput(), failure.getMessage());
            assertFalse(Files.exists(file), "a run that did not start is not recorded");
            assertEquals(List.of(), log.messages(Level.INFO));
        }
        assertEquals(text.toString(), Files.readString(replayed), "the replayed file is untouched");
    }

    @Test
    void aStartThatWorksSaysWhereAndTheHeaderHoldsEveryShapingKey() throws Exception {
        Path file = dir.resolve("run.rec");
        Properties properties = properties("0", file);
        properties.setProperty("wss.shaping.queueMs", "35");
        try (LogCapture log = LogCapture.of(Recorder.class.getName(), Level.INFO)) {
            Server server = server(properties);
            try {
                server.start();
                assertEquals(List.of("recording the run to " + file.toAbsolutePath()), log.messages(Level.INFO));
            } finally {
                server.close();
            }
        }
        Map<String, String> settings = RecordingReader.read(file).header().settings();
        assertEquals("35", settings.get("wss.shaping.queueMs"));
        for (Setting setting : ConfigKeys.SERVER) {
            if (setting.key().startsWith("wss.shaping")) {
                assertTrue(settings.containsKey(setting.key()), setting.key() + " is recorded: " + settings);
            }
        }
    }
}
