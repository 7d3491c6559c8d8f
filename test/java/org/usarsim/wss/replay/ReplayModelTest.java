package org.usarsim.wss.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.ModelInputException;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.recording.Entry;

/**
 * The replay model driven with a fake server and a clock the test moves: kicks, link states,
 * GETSS, jumps, speed, loop and end, and what it says of bad recordings.
 */
class ReplayModelTest {

    private static final long MS = 1_000_000L;

    @TempDir
    Path dir;

    private final AtomicLong now = new AtomicLong(TimeUnitHours.ONE);
    private final FakeLinks links = new FakeLinks();
    private final List<String> events = new CopyOnWriteArrayList<>();
    private final List<ModelPoll> polls = new CopyOnWriteArrayList<>();
    private final LogCapture log = LogCapture.of(ReplayPropagationModel.class.getName(), Level.FINE);
    private ReplayPropagationModel model;

    /** An hour in nanoseconds: the fake clock's origin, far from 0. */
    private static final class TimeUnitHours {
        static final long ONE = 3_600_000_000_000L;
    }

    @AfterEach
    void stop() {
        if (model != null) {
            model.shutdown();
        }
        log.close();
    }

    /** Alpha, Bravo and Charlie polled every 200 ms; Bravo drives off at 400 and back at 800; Charlie's battery is empty at 1000. */
    private static Recordings run() {
        return new Recordings()
                .entry(new Entry.Walls(180, List.of(new Wall(0, 5, 20, 5), new Wall(0, -5, 20, -5, "glass"))))
                .robot("Alpha", 0, 0, false).robot("Bravo", 10, 0, false).robot("Charlie", 20, 0, false)
                .pair("Alpha", "Bravo", -60, true).pair("Alpha", "Charlie", -80, true).pair("Bravo", "Charlie", -61, true)
                .poll(200)
                .robot("Alpha", 0, 0, false).robot("Bravo", 50, 0, false).robot("Charlie", 20, 0, false)
                .pair("Alpha", "Bravo", -95, false).pair("Alpha", "Charlie", -80.5, true).pair("Bravo", "Charlie", -90, true)
                .poll(400)
                .robot("Alpha", 0, 0, false).robot("Bravo", 50, 0, false).robot("Charlie", 20, 0, false)
                .pair("Alpha", "Bravo", -94, false).pair("Alpha", "Charlie", -81, true).pair("Bravo", "Charlie", -89, true)
                .poll(600)
                .robot("Alpha", 0, 0, false).robot("Bravo", 10, 0, false).robot("Charlie", 20, 0, false)
                .pair("Alpha", "Bravo", -61, true).pair("Alpha", "Charlie", -82, true).pair("Bravo", "Charlie", -62, true)
                .poll(800)
                .robot("Alpha", 0, 0, false).robot("Bravo", 10, 0, false).robot("Charlie", 20, 0, true)
                .pair("Alpha", "Bravo", -62, true)
                .poll(1000);
    }

    private ReplayPropagationModel started(Path file, String... settings) throws ModelStartException {
        model = new ReplayPropagationModel(now::get);
        Map<String, String> values = new LinkedHashMap<>();
        values.put("replay.file", file.toString());
        for (int i = 0; i < settings.length; i += 2) {
            values.put(settings[i], settings[i + 1]);
        }
        model.configure(new ModelSettings(values));
        model.setRobotLinkModel(links);
        model.setEventListener(new WssEventListener() {
            @Override
            public void robotOutOfBattery(String robot) {
                events.add("OUT_OF_BATTERY " + robot);
            }

            @Override
            public void connectionOutOfRange(String from, String to, double strength, double distance) {
                events.add("OUT_OF_RANGE " + from + " " + to + " " + strength + " " + distance);
            }

            @Override
            public void connectionInRange(String from, String to) {
                events.add("IN_RANGE " + from + " " + to);
            }

            @Override
            public void polled(ModelPoll poll) {
                polls.add(poll);
            }
        });
        model.start();
        return model;
    }

    private Replay controls() {
        return model.replay().orElseThrow();
    }

    /** Moves the clock on. */
    private void after(long millis) {
        now.addAndGet(millis * MS);
    }

    /** Waits until GETSS Alpha -> Bravo answers {@code strength}: the poll that has it is applied. */
    private void awaitAlphaBravo(double strength) {
        Wait.until("GETSS Alpha Bravo is " + strength + " (it is " + model.getSignalStrengthForPair("Alpha", "Bravo") + ")",
                () -> model.getSignalStrengthForPair("Alpha", "Bravo") == strength);
    }

    @Test
    void kicksTheRobotsThePollDoesNotListOrWhoseBatteryIsEmptyAndSetsTheRecordedStates() throws Exception {
        links.register("Alpha", "Bravo", "Charlie", "Zed");
        started(run().write(dir.resolve("run.rec"), 1001));
        Wait.until("Zed kicked", () -> links.kicked().contains("Zed"));
        awaitAlphaBravo(-60);
        assertEquals(1, log.count(Level.INFO, "kicking Zed: the recording does not list it at 00:00"), log.toString());
        assertEquals(Map.of(RobotPair.of("Alpha", "Bravo"), true, RobotPair.of("Alpha", "Charlie"), true,
                RobotPair.of("Bravo", "Charlie"), true), links.applied().get(0), "every pair of present robots in one go");
        ModelPoll first = polls.get(0);
        assertEquals(List.of(new ModelPoll.Kick("Zed", false)), first.kicks());
        assertEquals(3, first.robots().size());
        assertEquals(3, first.pairs().size());
        assertEquals(List.of(new Wall(0, 5, 20, 5), new Wall(0, -5, 20, -5, "glass")), first.walls(), "with their materials");
        assertEquals(List.of(), events, "nothing changed at the first poll");

        after(400);
        awaitAlphaBravo(-95);
        // GETSS has the poll as soon as it is published; its states and events follow at once.
        Wait.until("the break applied and said", () -> links.isBroken("Alpha", "Bravo") && events.size() == 1);
        assertFalse(links.isBroken("Alpha", "Charlie"));
        assertEquals(List.of("OUT_OF_RANGE Alpha Bravo -95.0 50.0"), events);

        after(600);
        awaitAlphaBravo(-62);
        Wait.until("Charlie kicked", () -> links.kicked().contains("Charlie"));
        Wait.until("the resume said", () -> events.size() == 3);
        assertEquals(List.of("OUT_OF_RANGE Alpha Bravo -95.0 50.0", "OUT_OF_BATTERY Charlie", "IN_RANGE Alpha Bravo"), events,
                "the kicks first, then the pairs");
        assertEquals(1, log.count(Level.INFO, "kicking Charlie: its battery is empty at 00:01"), log.toString());
        assertFalse(links.isBroken("Alpha", "Bravo"));
        assertEquals(Map.of(RobotPair.of("Alpha", "Bravo"), true), links.applied().get(links.applied().size() - 1));
    }

    @Test
    void getssIsTheRecordedStrengthOfThePollBothWaysAndTheMapItsPositionsAndWalls() throws Exception {
        links.register("Alpha", "Bravo", "Charlie");
        started(run().write(dir.resolve("run.rec"), 1001));
        double[][] strengths = {{-60, -80, -61}, {-95, -80.5, -90}, {-94, -81, -89}, {-61, -82, -62}};
        for (double[] poll : strengths) {
            after(200);
            awaitAlphaBravo(poll[0]);
            assertEquals(poll[0], model.getSignalStrengthForPair("Bravo", "Alpha"));
            assertEquals(poll[1], model.getSignalStrengthForPair("Alpha", "Charlie"));
            assertEquals(poll[2], model.getSignalStrengthForPair("Charlie", "Bravo"));
            assertEquals(poll[0] > -93, model.connectionIsPossibleForPair("Alpha", "Bravo"));
            assertEquals(poll[0] > -93, model.connectionIsPossibleForPair("Bravo", "Alpha"));
        }
        assertEquals(Double.NaN, model.getSignalStrengthForPair("Alpha", "Nobody"));
        assertTrue(model.connectionIsPossibleForPair("Alpha", "Nobody"), "an unknown robot may connect until it is kicked");
        assertEquals(new Position(10, 0, 0), model.positionOf("Bravo").orElseThrow());
        assertTrue(model.positionOf("Nobody").isEmpty());
        assertEquals(List.of(new Wall(0, 5, 20, 5), new Wall(0, -5, 20, -5, "glass")), model.walls(), "with their materials");
        assertEquals(-93, model.cutoff());
        assertEquals(Double.NaN, model.rangeFor("Alpha", "Bravo"));
    }

    @Test
    void aJumpAppliesAtOnceBackAndForthAndBreaksAsABreakDoes() throws Exception {
        links.register("Alpha", "Bravo");
        started(run().write(dir.resolve("run.rec"), 1001));
        awaitAlphaBravo(-60);
        controls().pause();
        controls().jump(0.5);
        awaitAlphaBravo(-95);
        Wait.until("the jump broke the pair through applyLinkStates", () -> links.isBroken("Alpha", "Bravo"));
        assertEquals(0.5, controls().timeSeconds());
        assertFalse(controls().playing());
        controls().jump(0.8);
        awaitAlphaBravo(-61);
        Wait.until("the jump resumed the pair", () -> !links.isBroken("Alpha", "Bravo"));
        controls().jump(0);
        awaitAlphaBravo(-60);
        Wait.until("both said", () -> events.size() == 2);
        assertEquals(List.of("OUT_OF_RANGE Alpha Bravo -95.0 50.0", "IN_RANGE Alpha Bravo"), events);
        for (double end : new double[] {1.001, 0.3, 0.7, 0.9}) {
            controls().jump(end); // seconds whose milliseconds are not exact in binary
            assertEquals(end, controls().timeSeconds(), 1e-9);
        }
        controls().jump(1.001);
        awaitAlphaBravo(-62);
        assertEquals(1.001, controls().durationSeconds());
        assertThrows(IllegalArgumentException.class, () -> controls().jump(1.5));
        assertThrows(IllegalArgumentException.class, () -> controls().jump(-0.1));
        Wait.until("whatever jumps the thread saw on the way, the last poll's state", () -> !links.isBroken("Alpha", "Bravo"));
    }

    @Test
    void speedAndStartAreTheSettingsAndTheControlsChangeTheSpeed() throws Exception {
        links.register("Alpha", "Bravo");
        started(run().write(dir.resolve("run.rec"), 1001), "replay.speed", "2", "replay.start", "0.2");
        assertEquals(2, controls().speed());
        awaitAlphaBravo(-60);
        after(100);
        awaitAlphaBravo(-95);
        assertEquals(0.4, controls().timeSeconds(), 1e-9);
        controls().speed(0.25);
        after(400);
        assertEquals(0.5, controls().timeSeconds(), 1e-9);
        after(400);
        awaitAlphaBravo(-94);
        assertThrows(IllegalArgumentException.class, () -> controls().speed(9));
        assertThrows(IllegalArgumentException.class, () -> controls().speed(0.2));
        assertEquals(1, log.count(Level.INFO, "from 00:00 at 2x"), log.toString());
    }

    @Test
    void withoutLoopItHoldsTheLastPollAtTheEnd() throws Exception {
        links.register("Alpha", "Bravo");
        started(run().write(dir.resolve("run.rec"), 1001));
        awaitAlphaBravo(-60);
        after(5_000);
        awaitAlphaBravo(-62);
        Wait.until("the end said", () -> log.count(Level.INFO, "the replay reached its end at 00:01") == 1);
        assertFalse(controls().playing());
        assertEquals(1.001, controls().timeSeconds());
        after(5_000);
        controls().pause(); // a control wakes the thread: it still holds the last poll
        assertEquals(-62, model.getSignalStrengthForPair("Alpha", "Bravo"));
        controls().play();
        assertTrue(controls().playing(), "play at the end plays from the start");
        awaitAlphaBravo(-60);
    }

    @Test
    void withLoopItWrapsToTheStart() throws Exception {
        links.register("Alpha", "Bravo");
        started(run().write(dir.resolve("run.rec"), 1001), "replay.loop", "true", "replay.start", "0.9");
        awaitAlphaBravo(-61);
        after(100);
        awaitAlphaBravo(-62);
        after(200);
        awaitAlphaBravo(-60);
        assertTrue(controls().playing());
        assertEquals(0.199, controls().timeSeconds(), 1e-9);
        assertEquals(1, log.count(Level.INFO, "looping"), log.toString());
    }

    @Test
    void aRobotThatRegistersWhileTheReplayHoldsStillIsDecidedAtOnce() throws Exception {
        links.register("Alpha");
        started(run().write(dir.resolve("run.rec"), 1001));
        awaitAlphaBravo(-60);
        controls().pause();
        links.register("Stranger", "Bravo");
        Wait.until("the stranger kicked", () -> links.kicked().contains("Stranger"));
        Wait.until("Alpha - Bravo decided", () -> links.applied().stream().anyMatch(a -> a.containsKey(RobotPair.of("Alpha", "Bravo"))));
        assertEquals(List.of("Stranger"), links.kicked());
    }

    /**
     * Issue 26, item 10: a robot that registers while the replay applies a poll (between its look
     * at the registered robots and the poll's end) was counted as applied without being checked,
     * and a replay holding still at its end never looked at it again.
     */
    @Test
    void aRobotThatRegistersWhileAPollIsAppliedIsKickedAtTheEnd() throws Exception {
        links.register("Alpha", "Bravo");
        started(new Recordings().robot("Alpha", 0, 0, false).robot("Bravo", 10, 0, false)
                .pair("Alpha", "Bravo", -67, true).poll(100).write(dir.resolve("short.rec"), 150));
        after(1_000);
        Wait.until("the end said", () -> log.count(Level.INFO, "the replay reached its end at 00:00") == 1);
        awaitAlphaBravo(-67);
        links.registerThenAnother("Zed", "Stranger"); // the stranger registers while the replay kicks Zed
        Wait.until("the stranger kicked", () -> links.kicked().contains("Stranger"));
        assertEquals(List.of("Zed", "Stranger"), links.kicked());
        assertEquals(1, log.count(Level.INFO, "kicking Stranger: the recording does not list it at 00:00"), log.toString());
    }

    /**
     * Issue 26, item 4: the recorded robots left before the recording's end (its last polls list
     * them without pair rows); a replay at its end keeps each pair's last recorded state.
     */
    @Test
    void atTheEndAPairTheLastPollsHaveNoRowForKeepsItsLastRecordedState() throws Exception {
        links.register("Alpha", "Bravo", "Charlie");
        started(new Recordings()
                .robot("Alpha", 0, 0, false).robot("Bravo", 50, 0, false).robot("Charlie", 20, 0, false)
                .pair("Alpha", "Bravo", -95, false).pair("Alpha", "Charlie", -80, true).pair("Bravo", "Charlie", -90, true)
                .poll(200)
                .robot("Alpha", 0, 0, false).robot("Bravo", 50, 0, false).robot("Charlie", 20, 0, false)
                .pair("Alpha", "Charlie", -81, true)
                .poll(400)
                .robot("Alpha", 0, 0, false).robot("Bravo", 50, 0, false).robot("Charlie", 20, 0, false)
                .poll(600)
                .write(dir.resolve("left.rec"), 700), "replay.start", "0.7");
        awaitAlphaBravo(-95);
        assertEquals(-81, model.getSignalStrengthForPair("Charlie", "Alpha"), "the last row, not an older one");
        assertEquals(-90, model.getSignalStrengthForPair("Bravo", "Charlie"));
        assertFalse(model.connectionIsPossibleForPair("Alpha", "Bravo"));
        Wait.until("the states applied", () -> links.isBroken("Alpha", "Bravo"));
        assertFalse(links.isBroken("Alpha", "Charlie"));
        ModelPoll last = polls.get(polls.size() - 1);
        assertEquals(List.of(new ModelPoll.Pair("Alpha", "Bravo", -95, 0, false), new ModelPoll.Pair("Alpha", "Charlie", -81, 0, true),
                new ModelPoll.Pair("Bravo", "Charlie", -90, 0, true)), last.pairs());
    }

    @Test
    void aRecordingCutShortIsReplayedWithOneWarning() throws Exception {
        Path file = dir.resolve("crashed.rec");
        Files.writeString(file, run().text(-1) + "1200 poll 3 3\n1200 robot Alpha 0 0", StandardCharsets.UTF_8);
        links.register("Alpha", "Bravo");
        started(file);
        awaitAlphaBravo(-60);
        assertEquals(List.of(file + " was cut short (a run that did not stop): replaying up to its last whole line at 00:01"),
                log.messages(Level.WARNING));
        assertEquals(1.2, controls().durationSeconds(), "the last whole line's time");
    }

    @Test
    void unknownLinesAreSkippedAndSaidOnce() throws Exception {
        String text = run().text(1001);
        text = text.replace("400 poll", "300 frobnicate 1 2\n350 twiddle\n400 poll");
        Path file = Files.writeString(dir.resolve("newer.rec"), text, StandardCharsets.UTF_8);
        links.register("Alpha", "Bravo");
        started(file);
        awaitAlphaBravo(-60);
        after(400);
        awaitAlphaBravo(-95);
        List<String> warnings = log.messages(Level.WARNING);
        assertEquals(1, warnings.size(), warnings.toString());
        assertTrue(warnings.get(0).startsWith(file + ": skipped 2 lines (2 with a keyword this WSS does not know, 0 that cannot be read);"
                + " the first: line "), warnings.get(0));
        assertTrue(warnings.get(0).endsWith("an unknown keyword frobnicate"), warnings.get(0));
    }

    @Test
    void theStartLineSaysWhatIsReplayed() throws Exception {
        Path file = run().write(dir.resolve("run.rec"), 1001);
        started(file);
        assertEquals(List.of("replaying " + file + ": recorded with ObstaclePropagationModel, 00:01 long, 5 polls, 3 robots"
                + " [Alpha, Bravo, Charlie]; from 00:00 at 1x"), log.messages(Level.INFO).subList(0, 1));
        assertTrue(model.isActive());
        model.shutdown();
        assertFalse(model.isActive());
        assertFalse(controls().playing());
    }

    @Test
    void badRecordingsAreRefusedWithOneLine() throws Exception {
        Map<String, String> files = new LinkedHashMap<>();
        files.put("hello.txt", "hello\n");
        files.put("v2.rec", "WSS-RECORDING 2\nwss 9.0\n");
        files.put("empty.rec", "");
        files.put("nopolls.rec", new Recordings().text(500));
        List<String> messages = new ArrayList<>();
        for (Map.Entry<String, String> file : files.entrySet()) {
            Path path = Files.writeString(dir.resolve(file.getKey()), file.getValue(), StandardCharsets.UTF_8);
            messages.add(refused(path.toString()));
        }
        messages.add(refused(dir.resolve("missing.rec").toString()));
        messages.add(refused(""));
        assertTrue(messages.get(0).contains("hello.txt is not a WSS recording"), messages.get(0));
        assertTrue(messages.get(1).contains("v2.rec is a recording of format version 2; this WSS reads version 1"), messages.get(1));
        assertTrue(messages.get(2).endsWith("empty.rec is empty: not a WSS recording (one starts with WSS-RECORDING 1)"), messages.get(2));
        assertTrue(messages.get(3).contains("nopolls.rec holds no poll (recorded with ObstaclePropagationModel): nothing to replay"),
                messages.get(3));
        assertTrue(messages.get(4).contains("missing.rec: no such file"), messages.get(4));
        assertEquals("replay.file is empty: name the recording to replay (docs/replay.md)", messages.get(5));
        messages.forEach(message -> assertFalse(message.contains("\n"), message));
    }

    @Test
    void aStartPastTheEndIsRefused() throws Exception {
        Path file = run().write(dir.resolve("run.rec"), 1001);
        model = new ReplayPropagationModel(now::get);
        model.configure(new ModelSettings(Map.of("replay.file", file.toString(), "replay.start", "2")));
        model.setRobotLinkModel(links);
        ModelInputException e = assertThrows(ModelInputException.class, model::start);
        assertEquals("replay.start = 2 s is past the end of " + file + " (00:01)", e.getMessage());
    }

    /** The message of the start that refused this replay.file. */
    private String refused(String file) {
        ReplayPropagationModel refusing = new ReplayPropagationModel(now::get);
        refusing.configure(new ModelSettings(Map.of("replay.file", file)));
        refusing.setRobotLinkModel(links);
        ModelStartException e = assertThrows(ModelStartException.class, refusing::start);
        assertInstanceOf(ModelInputException.class, e, "bad input: headless exits 2");
        assertFalse(refusing.isActive());
        return e.getMessage();
    }
}
