package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.replay.Recordings;
import org.usarsim.wss.protocol.Replies;

/** Headless with the replay model: a recording served to robots; a bad one is bad input (exit 2, one line). */
@Tag("slow")
class HeadlessReplayTest {

    @TempDir
    Path dir;

    private Path config(Path recording, String... more) throws Exception {
        Map<String, String> values = new java.util.LinkedHashMap<>();
        values.put("wss.model", "ReplayPropagationModel");
        values.put("replay.file", recording.toString());
        for (int i = 0; i < more.length; i += 2) {
            values.put(more[i], more[i + 1]);
        }
        return ServerProcess.config(dir, values);
    }

    @Test
    void aRecordingThatIsNotOneExitsTwoWithOneLine() throws Exception {
        Path notOne = Files.writeString(dir.resolve("notes.txt"), "hello\n", StandardCharsets.UTF_8);
        ServerProcess server = ServerProcess.start("--headless", "--config", config(notOne).toString());
        try {
            assertEquals(Main.BAD_INPUT, server.awaitExit(), "stderr: " + server.stderr());
            String error = server.stderr().strip();
            assertEquals("wss: ReplayPropagationModel did not start: " + notOne + " is not a WSS recording (its first line is not "
                    + "WSS-RECORDING 1)", error);
            assertTrue(server.stdoutSoFar().stream().noneMatch(line -> line.contains("WSS listening")), server.stdoutSoFar().toString());
        } finally {
            server.kill();
        }
    }

    @Test
    void anotherVersionAMissingFileAndNoFileAreBadInputToo() throws Exception {
        Path v2 = Files.writeString(dir.resolve("v2.rec"), "WSS-RECORDING 2\n", StandardCharsets.UTF_8);
        Map<Path, String> expected = Map.of(
                v2, v2 + " is a recording of format version 2; this WSS reads version 1",
                dir.resolve("gone.rec"), dir.resolve("gone.rec") + ": no such file",
                Path.of(""), "replay.file is empty: name the recording to replay (docs/replay.md)");
        for (Map.Entry<Path, String> bad : expected.entrySet()) {
            MainRun run = MainRun.of("--headless", "--config", config(bad.getKey()).toString());
            assertEquals(Main.BAD_INPUT, run.exitCode(), run.stderr());
            assertEquals("wss: ReplayPropagationModel did not start: " + bad.getValue(), run.stderr().strip());
        }
    }

    @Test
    void robotsGetTheRecordedStrengthAndOneItNeverHadIsKicked() throws Exception {
        Path recording = new Recordings()
                .robot("Alpha", 0, 0, false).robot("Bravo", 10, 0, false)
                .pair("Alpha", "Bravo", -67.2345, true).poll(100)
                .write(dir.resolve("short.rec"), 150);
        ServerProcess server = ServerProcess.start("--headless", "--config", config(recording, "replay.speed", "8").toString());
        try {
            int port = Integer.parseInt(server.awaitListening().group(1));
            Wait.until("the start-up says the links are not shaped (issue 26, item 9)", () -> server.stdoutSoFar().stream()
                    .anyMatch(line -> line.contains("INFO links are not shaped (wss.shaping = off)")));
            // The replay's thread may say its end before or after the listening line: look at every line so far.
            Wait.until("the replay reached its end", () -> server.stdoutSoFar().stream()
                    .anyMatch(line -> line.contains("the replay reached its end at 00:00")));
            assertTrue(server.stdoutSoFar().stream().anyMatch(line -> line.contains("INFO replaying " + recording
                    + ": recorded with ObstaclePropagationModel, 00:00 long, 1 poll, 2 robots [Alpha, Bravo]; from 00:00 at 8x")),
                    server.stdoutSoFar().toString());
            try (TestRobot alpha = new TestRobot(port, "127.0.0.1");
                    TestRobot bravo = new TestRobot(port, "127.0.0.1");
                    TestRobot stranger = new TestRobot(port, "127.0.0.1")) {
                alpha.init("Alpha");
                bravo.init("Bravo");
                assertEquals(Replies.signal("Bravo", -67.2345), alpha.ask("GETSS {Robot Bravo}"));
                assertEquals(Replies.signal("Alpha", -67.2345), bravo.ask("GETSS {Robot Alpha}"));
                stranger.init("Stranger");
                server.awaitLine(line -> line.contains("kicking Stranger: the recording does not list it at 00:00"));
                Wait.until("the stranger's connection closed", () -> {
                    try {
                        stranger.readLine();
                        return false;
                    } catch (java.io.IOException e) {
                        return true;
                    }
                });
                assertFalse(server.stdoutSoFar().stream().anyMatch(line -> line.contains("kicking Alpha")));
            }
            server.sigterm();
            assertEquals(Main.OK, server.awaitExit());
        } finally {
            server.kill();
        }
    }
}
