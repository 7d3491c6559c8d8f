package org.usarsim.wss.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.simulator.ModelRig;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.model.simulator.Shadowing;
import org.usarsim.wss.protocol.Strengths;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.Recorder;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingReader;

/**
 * A run of the DistanceOnly model with shadowing, recorded: its strengths are the formula's plus
 * the seeded field's (what a second run with the same seed and positions gives), the recording's
 * header keeps the shadowing's settings and the seed, and a replay of it answers GETSS as the run did.
 */
@Tag("slow")
class ShadowedReplayTest {

    private static final double[][] PLACES = {{4, 6, 0.5}, {4.5, 6, 0.5}, {30, -12, 0.5}};

    @TempDir
    Path dir;

    @Test
    void theRunsShadowedStrengthsAreTheSeedsAndTheReplayAnswersThem() throws Exception {
        Map<String, String> given = Map.of("shadowing.sigma", "10", "shadowing.distance", "5", "wss.seed", "7");
        DistanceOnlyPropagationModel live = new DistanceOnlyPropagationModel();
        Map<String, String> settings = new LinkedHashMap<>();
        for (Setting setting : live.settings()) {
            settings.put(setting.key(), given.getOrDefault(setting.key(), setting.defaultValue()));
        }
        settings.put("wss.seed", given.get("wss.seed")); // the run's seed, as Server.recordedSettings puts it after the model's
        Recorder recorder = Recorder.create(dir.resolve("shadowed.rec"), live.name(), settings);
        List<String> answered = new ArrayList<>();
        Shadowing field = new Shadowing(10, 5, 7);
        PathLoss loss = new PathLoss(-49.67, 1, 2, -93);
        try (ModelRig rig = new ModelRig(live, given)) {
            rig.server.hub.addListener(recorder);
            rig.robot("A", 1, 2, 0.5);
            rig.robot("B", 1, 2, 0.5);
            for (double[] place : PLACES) {
                rig.sim.place("B", place[0], place[1], place[2]);
                rig.polls(1);
                ReportedRobot a = new ReportedRobot("A", 1, 2, 0.5, false);
                ReportedRobot b = new ReportedRobot("B", place[0], place[1], place[2], false);
                double formula = loss.strength(a.distanceTo(b));
                double strength = rig.model.getSignalStrengthForPair("A", "B");
                assertEquals(formula + field.db(a, b), strength, 1e-9, "the formula plus the seed's field at " + b);
                assertNotEquals(formula, strength, 1e-3, "shadowed");
                answered.add(Strengths.format(strength));
            }
        } finally {
            recorder.close();
        }

        Recording recording = RecordingReader.read(recorder.file());
        assertEquals("7", recording.header().settings().get("wss.seed"));
        assertFalse(recording.header().settings().containsKey("radio.seed"), "no seed of the model's own");
        assertEquals("10", recording.header().settings().get("shadowing.sigma"));
        assertEquals("5", recording.header().settings().get("shadowing.distance"));
        List<String> recorded = new ArrayList<>();
        for (Entry.Poll poll : recording.polls()) {
            for (var pair : poll.pairs()) {
                String value = Strengths.format(pair.strength());
                if (recorded.isEmpty() || !recorded.get(recorded.size() - 1).equals(value)) {
                    recorded.add(value);
                }
            }
        }
        assertTrue(recorded.containsAll(answered), "every answer is recorded: " + answered + " in " + recorded);

        AtomicLong now = new AtomicLong(3_600_000_000_000L);
        ReplayPropagationModel replay = new ReplayPropagationModel(now::get);
        replay.configure(new ModelSettings(Map.of("replay.file", recorder.file().toString())));
        replay.setRobotLinkModel(new FakeLinks());
        replay.setEventListener(new WssEventListener() { });
        replay.start();
        try {
            List<String> replayed = new ArrayList<>();
            for (Entry.Poll poll : recording.polls()) {
                if (poll.pairs().isEmpty()) {
                    continue; // before B registered
                }
                now.set(3_600_000_000_000L + poll.millis() * 1_000_000L);
                String expected = Strengths.format(poll.pairs().get(0).strength());
                Wait.until("the replay at " + poll.millis() + " ms answers " + expected,
                        () -> Strengths.format(replay.getSignalStrengthForPair("A", "B")).equals(expected));
                if (replayed.isEmpty() || !replayed.get(replayed.size() - 1).equals(expected)) {
                    replayed.add(expected);
                }
            }
            assertTrue(replayed.containsAll(answered), "the replay answers as the run did: " + answered + " in " + replayed);
        } finally {
            replay.shutdown();
        }
    }
}
