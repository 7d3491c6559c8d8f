package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;

/**
 * Fuzzed simulator replies: random bytes and mutations of valid POSITIONS and NUMOBS lines. The
 * reader either reads them or names what is wrong, nothing else escapes; through a running model,
 * garbage costs one log line and keeps the last good positions. Seeded: the seed is in every
 * failure message, {@code -Dwss.fuzz.seed=N} replays a run ({@code -Dwss.fuzz.lines=N}: how many
 * lines, 100,000 by default).
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class SimulatorRepliesFuzzTest {

    private static final String[] VALID = {
        "POSITIONS {Robots 2} {Name Robot1 Location 1.2500,-3.0000,0.4500 BatteryEmpty False}"
            + " {Name Robot2 Location 10.0000,2.5000,0.4500 BatteryEmpty True}",
        "POSITIONS {Robots 1} {Name A Location 0.0000,0.0000,0.0000 BatteryEmpty False}",
        "POSITIONS {Robots 0}",
        "NUMOBS {From Robot1} {To Robot2} {ObstCount 3.0000}",
        "NUMOBS {From A} {To B} {ObstCount -1.0000}",
    };
    private static final String[] ODD = {"{", "}", "{}", " ", "\t", "\u0000", "\u000B", "é", "機", "\uFFFD", ",", ",,",
        "NaN", "Infinity", "-Infinity", "1e309", "-0", "99999999999999999999", "2147483648", "-1", "True", "Robots", "Name",
        "Location", "BatteryEmpty", "POSITIONS", "NUMOBS", "ObstCount", "0x10", "1,2", "1,2,3,4"};

    private final long seed = Long.getLong("wss.fuzz.seed", new Random().nextLong());
    private final String replay = " (seed " + seed + "; replay with -Dwss.fuzz.seed=" + seed + ")";

    @Test
    void everyFuzzedReplyIsReadOrRefusedWithAReason() {
        Random random = new Random(seed);
        int read = 0;
        int refused = 0;
        int lines = Integer.getInteger("wss.fuzz.lines", 100_000);
        for (int i = 0; i < lines; i++) {
            String line = fuzzed(random);
            try {
                // As SimulatorConnection does: the type word picks the reader; any other type is refused.
                String type = SimulatorReplies.type(line);
                if (type.equals(SimulatorReplies.POSITIONS)) {
                    Map<String, ReportedRobot> robots = SimulatorReplies.positions(line);
                    for (ReportedRobot robot : robots.values()) {
                        assertTrue(Double.isFinite(robot.x()) && Double.isFinite(robot.y()) && Double.isFinite(robot.z()),
                                () -> "a position that is not finite from '" + line + "'" + replay);
                    }
                    read++;
                } else if (type.equals(SimulatorReplies.NUMOBS)) {
                    double count = SimulatorReplies.obstacles(line).count();
                    assertTrue(Double.isNaN(count) || count >= 0 && Double.isFinite(count),
                            () -> "count " + count + " from '" + line + "'" + replay);
                    read++;
                }
            } catch (SimulatorReplyException e) {
                assertOneLine(e, line);
                refused++;
            } catch (RuntimeException e) {
                throw new AssertionError("'" + line + "' threw " + e + replay, e);
            }
        }
        assertTrue(read > lines / 100 && refused > lines / 10, "both kinds were tried: " + read + " read, " + refused + " refused" + replay);
    }

    @Test
    void garbageThroughARunningModelIsLoggedOnceAndTheLastGoodPositionsAreKept() throws Exception {
        Random random = new Random(seed);
        ManualClock clock = new ManualClock();
        try (ModelRig rig = new ModelRig(new DistanceOnlyPropagationModel(clock), Map.of("distance.n", "3"), clock)) {
            TestRobot a = rig.robot("A", 0, 0, 0);
            rig.robot("B", 10, 0, 0);
            rig.polls(1);
            String before = a.ask("GETSS {Robot B}");
            long connections = rig.sim.connectionCount();
            rig.sim.garbage(() -> garbage(random));
            rig.polls(6); // each attempt on a new connection, answered with garbage
            Wait.until("6 garbage replies", () -> rig.sim.connectionCount() >= connections + 5);
            assertEquals(before, a.ask("GETSS {Robot B}"), "the last good positions" + replay);
            assertEquals(List.of("A", "B"), rig.server.hub.getListOfRegisteredRobots(), replay);
            assertEquals(1, rig.logLines(Level.WARNING, "lost the simulator"), rig.log + replay);
            assertEquals(0, rig.logLines(Level.WARNING, "a poll failed"), rig.log + replay);

            rig.sim.mode(FakeSimulator.Mode.ANSWER);
            rig.polls(1);
            assertEquals(1, rig.logLines(Level.INFO, "answers again"), "the model says the simulator is back" + replay);
            rig.sim.place("B", 100, 0, 0);
            rig.polls(1);
            Wait.until("the model decides from new positions", () -> rig.events("OUT_OF_RANGE").size() == 1);
        }
    }

    private void assertOneLine(SimulatorReplyException e, String line) {
        String message = e.getMessage();
        assertTrue(message != null && !message.isBlank() && message.indexOf('\n') < 0,
                () -> "'" + line + "' refused with '" + message + "'" + replay);
    }

    /** A line the model cannot take for a GETPOS answer: not a POSITIONS it reads, not a NUMOBS, not blank. */
    private static String garbage(Random random) {
        while (true) {
            String line = fuzzed(random);
            if (line.isBlank() || SimulatorReplies.type(line).equals(SimulatorReplies.NUMOBS)) {
                continue;
            }
            try {
                SimulatorReplies.positions(line);
            } catch (SimulatorReplyException e) {
                return line;
            }
        }
    }

    /** Random bytes (as the reader decodes them) or a valid reply with one to three mutations; never CR or LF inside. */
    private static String fuzzed(Random random) {
        if (random.nextInt(4) == 0) {
            byte[] bytes = new byte[random.nextInt(120)];
            random.nextBytes(bytes);
            return new String(bytes, StandardCharsets.UTF_8).replace('\n', ' ').replace('\r', ' ');
        }
        StringBuilder line = new StringBuilder(VALID[random.nextInt(VALID.length)]);
        for (int m = random.nextInt(4); m > 0; m--) {
            int at = random.nextInt(line.length() + 1);
            switch (random.nextInt(6)) {
                case 0 -> line.insert(at, ODD[random.nextInt(ODD.length)]);
                case 1 -> {
                    if (at < line.length()) {
                        line.deleteCharAt(at);
                    }
                }
                case 2 -> line.setLength(at);
                case 3 -> {
                    int open = line.indexOf("{", at);
                    int close = open < 0 ? -1 : line.indexOf("}", open);
                    if (close > 0) {
                        String segment = line.substring(open, close + 1);
                        if (random.nextBoolean()) {
                            line.delete(open, close + 1);
                        } else {
                            line.insert(close + 1, segment);
                        }
                    }
                }
                case 4 -> {
                    if (at < line.length() && Character.isDigit(line.charAt(at))) {
                        line.setCharAt(at, (char) ('0' + random.nextInt(10)));
                    } else {
                        line.insert(at, random.nextInt(1000));
                    }
                }
                default -> line.insert(at, ODD[random.nextInt(ODD.length)].repeat(1 + random.nextInt(4)));
            }
        }
        return line.toString();
    }
}
