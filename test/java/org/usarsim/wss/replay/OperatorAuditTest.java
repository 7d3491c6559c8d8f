package org.usarsim.wss.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.logging.Level;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.CsvEventLog;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.net.LogLimiter;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.Recorder;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingReader;

/**
 * Issue 26, item 8: every FORCE and REPLAY that changed something is in the CSV event log and the
 * recording, however many an operator sends; the log's lines stay limited. A hub in the process
 * with the replay model, its operator on a socket.
 */
class OperatorAuditTest {

    @TempDir
    Path dir;

    @Test
    void everyForceAndReplayThatChangedSomethingIsInTheEventLogAndTheRecordingPastTheLogsLimit() throws Exception {
        Path recorded = new Recordings().robot("A", 0, 0, false).robot("B", 10, 0, false).pair("A", "B", -60, true).poll(0)
                .robot("A", 0, 0, false).robot("B", 10, 0, false).pair("A", "B", -61, true).poll(60_000)
                .write(dir.resolve("run.rec"), 60_000);
        ReplayPropagationModel model = new ReplayPropagationModel();
        model.configure(new ModelSettings(Map.of("replay.file", recorded.toString())));
        Path csvFile;
        Path recordingFile;
        try (LogCapture session = LogCapture.of("org.usarsim.wss.hub.tcp.ControlSession", Level.INFO);
                TestHub server = new TestHub(model, TestHub.config(true, 65536, 600, 1000, 30))) {
            CsvEventLog csv = CsvEventLog.create(dir);
            Recorder recorder = Recorder.create(dir.resolve("audit.rec"), model.name(), Map.of());
            server.hub.addListener(csv);
            server.hub.addListener(recorder);
            try (TestRobot operator = server.robot()) {
                operator.ask("REPLAY {State Pause}");
                operator.ask("REPLAY {State Pause}"); // paused already: nothing changed
                for (int second = 1; second <= 10; second++) {
                    operator.ask("REPLAY {Time " + second + "}");
                }
                operator.ask("REPLAY {Speed 4}");
                operator.ask("REPLAY {Speed 4}"); // the same speed: nothing changed
                for (int i = 0; i < 8; i++) {
                    operator.ask("FORCE {Robot A} {Peer B} {State " + (i % 2 == 0 ? "Down" : "Up") + "}");
                }
                operator.ask("FORCE {Robot A} {Peer B} {State Up}"); // forced up already: nothing changed
            }
            assertEquals(LogLimiter.FIRST, session.count(Level.INFO, "operator "), "the log's lines stay limited: " + session);
            server.hub.removeListener(csv);
            server.hub.removeListener(recorder);
            csv.close();
            recorder.close();
            csvFile = csv.file();
            recordingFile = recorder.file();
        }

        List<String> replays = new ArrayList<>();
        List<String> forces = new ArrayList<>();
        for (String line : Files.readAllLines(csvFile, StandardCharsets.UTF_8)) {
            String[] fields = line.split(",");
            if (fields[0].equals("REPLAY")) {
                replays.add(String.join(",", fields[2], fields[3], fields[4]));
            } else if (fields[0].equals("FORCED")) {
                forces.add(fields[4]);
            }
        }
        assertTrue(replays.get(0).matches("0(\\.\\d{1,3})?,1,PAUSE"), "paused where it was, to the millisecond: " + replays.get(0));
        List<String> expected = new ArrayList<>(List.of(replays.get(0)));
        for (int second = 1; second <= 10; second++) {
            expected.add(second + ",1,PAUSE");
        }
        expected.add("10,4,PAUSE");
        assertEquals(expected, replays, "every REPLAY that changed something, in order");
        assertEquals(List.of("DOWN", "UP", "DOWN", "UP", "DOWN", "UP", "DOWN", "UP"), forces);

        Recording recording = RecordingReader.read(recordingFile);
        List<String> recordedReplays = new ArrayList<>();
        int recordedForces = 0;
        for (Entry entry : recording.events()) {
            if (entry instanceof Entry.Replay replay) {
                recordedReplays.add(org.usarsim.wss.protocol.Strengths.format(replay.timeSeconds()) + "," + Math.round(replay.speed()) + ","
                        + (replay.playing() ? "PLAY" : "PAUSE"));
            } else if (entry instanceof Entry.Force) {
                recordedForces++;
            }
        }
        assertEquals(expected, recordedReplays, "the recording has them too");
        assertEquals(8, recordedForces);
        assertTrue(recording.unknownLines() == 0 && recording.unreadableLines() == 0, recording.firstProblem());
    }
}
