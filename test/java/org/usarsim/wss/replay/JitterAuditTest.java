package org.usarsim.wss.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.CsvEventLog;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.Recorder;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingReader;
import org.usarsim.wss.shaping.JitterConfig;
import org.usarsim.wss.shaping.JitterDistribution;
import org.usarsim.wss.shaping.LossTable;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * Issue 35, item 6: an operator's FORCE with a Jitter is in the CSV event log ({@code PINNED}) and
 * the recording ({@code pin}), read back as written; a replay of that recording answers as the run
 * did (the recorded strengths), the pin read and, as every operator's force, not replayed.
 */
class JitterAuditTest {

    @TempDir
    Path dir;

    private static HubConfig jittery() throws Exception {
        return TestHub.config(true, 65536, 600, 1000, 30).withShaping(new ShapingConfig(true, RateTable.DEFAULT, 2, true,
                ShapingConfig.DEFAULT_QUEUE_MS, LossTable.DEFAULT, new JitterConfig(5, JitterDistribution.NORMAL, false, 7)), Map.of());
    }

    private static ReplayPropagationModel replaying(Path file) throws Exception {
        ReplayPropagationModel model = new ReplayPropagationModel();
        model.configure(new ModelSettings(Map.of("replay.file", file.toString())));
        return model;
    }

    @Test
    void aForceWithAJitterIsRecordedAndAReplayOfTheRunAnswersAsTheRunDid() throws Exception {
        Path recorded = new Recordings().robot("A", 0, 0, false).robot("B", 10, 0, false).pair("A", "B", -60, true).poll(0)
                .write(dir.resolve("run.rec"), 60_000);
        ReplayPropagationModel model = replaying(recorded);
        Path csvFile;
        Path auditFile;
        String runAnswer;
        try (TestHub server = new TestHub(model, jittery())) {
            CsvEventLog csv = CsvEventLog.create(dir);
            Recorder recorder = Recorder.create(dir.resolve("audit.rec"), model.name(), Map.of());
            server.hub.addListener(csv);
            server.hub.addListener(recorder);
            AtomicInteger polls = new AtomicInteger();
            server.hub.addListener(new WssEventListener() {
                @Override
                public void polled(ModelPoll poll) {
                    polls.incrementAndGet();
                }
            });
            try (TestRobot operator = server.robot(); TestRobot a = server.robot()) {
                a.init("A");
                operator.ask("REPLAY {Time 0}"); // the poll applied again, so that the recording has one whenever the first came
                Wait.until("a poll reached the listeners after the recorder's start", () -> polls.get() > 0);
                assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot B} {Peer A} {State Up} {Rate 1M} {Jitter 20}"));
                assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot B} {Peer A} {State Up} {Rate 1M} {Jitter 20}"),
                        "the same pin again: nothing changed, nothing said");
                runAnswer = a.ask("GETSS {Robot B}");
            }
            server.hub.removeListener(csv);
            server.hub.removeListener(recorder);
            csv.close();
            recorder.close();
            csvFile = csv.file();
            auditFile = recorder.file();
        }
        List<String> pinned = Files.readAllLines(csvFile, StandardCharsets.UTF_8).stream().filter(line -> line.startsWith("PINNED,"))
                .map(line -> line.replaceFirst("^PINNED,[^,]+,", "")).toList();
        assertEquals(List.of("A,B,1000000,,20"), pinned, "the rate and the jitter, the delay not pinned, said once");

        Recording recording = RecordingReader.read(auditFile);
        List<Entry> pins = recording.events().stream().filter(Entry.Pin.class::isInstance).toList();
        assertEquals(1, pins.size(), recording.events().toString());
        Entry.Pin pin = (Entry.Pin) pins.get(0);
        assertEquals(List.of("A", "B", 1_000_000L, -1, 20), List.of(pin.first(), pin.second(), pin.bitsPerSecond(), pin.delayMs(),
                pin.jitterMs()));
        assertTrue(recording.unknownLines() == 0 && recording.unreadableLines() == 0, recording.firstProblem());

        try (TestHub replay = new TestHub(replaying(auditFile), jittery()); TestRobot a = replay.robot()) {
            a.init("A");
            assertEquals(runAnswer, a.ask("GETSS {Robot B}"), "the replay answers as the run did");
            assertTrue(replay.hub.snapshot().pairs().stream().noneMatch(pair -> pair.state() == PairState.FORCED_UP),
                    "the recorded force and pin are the run's operator's, not replayed: " + replay.hub.snapshot().pairs());
        }
    }
}
