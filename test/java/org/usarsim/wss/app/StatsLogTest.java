package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.logging.Level;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.HubSnapshot.RobotEntry;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * wss.statsInterval: the whole statistics table in the headless log, every so many seconds; with
 * links shaped, the rates each way and the robots' airtime too, and without, the table as it was.
 */
@Tag("slow")
class StatsLogTest {

    @Test
    void everyIntervalTheWholeTableIsLogged() throws Exception {
        try (TestHub server = new TestHub();
                TestRobot a = server.robotAt("127.0.0.1");
                TestRobot b = server.robotAt("127.0.0.2");
                LogCapture log = LogCapture.of(StatsLog.class.getName(), Level.INFO)) {
            a.init("A");
            b.initAccepting("B");
            a.dns("B", 0);
            try (StatsLog stats = StatsLog.every(1, server.hub)) {
                Wait.until("a table logged", () -> !log.messages(Level.INFO).isEmpty());
            }
            String table = log.messages(Level.INFO).get(0);
            List<String> lines = table.lines().toList();
            assertEquals("link statistics, 1 pair", lines.get(0), table);
            assertEquals(StatsLog.HEADER, lines.get(1));
            assertTrue(lines.get(2).matches("A - B +up +0 +- +0 +0 +0 +0 +0 +0 +0 +100\\.0 +-"), lines.get(2));
        }
    }

    @Test
    void noTableAtIntervalZero() throws Exception {
        try (TestHub server = new TestHub(); LogCapture log = LogCapture.of(StatsLog.class.getName(), Level.INFO)) {
            StatsLog.every(0, server.hub).close();
            assertTrue(Thread.getAllStackTraces().keySet().stream().noneMatch(t -> t.getName().equals("wss-stats-log")),
                    "no thread for a table never logged");
            assertEquals(List.of(), log.messages(Level.INFO));
        }
    }

    @Test
    void aRowSaysEveryNumber() {
        PairEntry pair = new PairEntry("Alpha", "Bravo", PairState.BROKEN, -93.5, 12.25, 1000, 2000, 10, 20, 3, 2, 1, 0.75,
                "out of range");
        String row = StatsLog.table(List.of(pair)).lines().toList().get(2);
        assertTrue(row.matches("Alpha - Bravo +broken +-93\\.5 +12\\.25 +1000 +2000 +10 +20 +3 +2 +1 +75\\.0  out of range"), row);
    }

    @Test
    void aFixedUdpPortsDirectionsEachHaveALineAfterThePairs() {
        PairEntry pair = new PairEntry("Base", "Scout", PairState.UP, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, null, 0, 0,
                org.usarsim.wss.hub.core.UdpCounts.Reading.NONE, new org.usarsim.wss.hub.core.UdpCounts.Reading(90, 9000, 4, 3, 10));
        List<String> lines = StatsLog.table(List.of(pair)).lines().toList();
        assertEquals(StatsLog.UDP_HEADER, lines.get(3));
        assertTrue(lines.get(4).matches("Scout > Base +90 +9000 +4 +3 +10"), lines.get(4));
        assertEquals(5, lines.size(), "no line for the way no datagram went");
    }

    @Test
    void withLinksShapedTheTableHasTheRatesEachWayAndTheRobotsAirtime() throws Exception {
        var shaped = TestHub.config(true, 65536, 600, 1000, 30).withShaping(new ShapingConfig(true, RateTable.DEFAULT, 2, true), Map.of());
        try (TestHub server = new TestHub(new NoopPropagationModel(), shaped);
                TestRobot a = server.robotAt("127.0.0.1");
                TestRobot b = server.robotAt("127.0.0.2");
                LogCapture log = LogCapture.of(StatsLog.class.getName(), Level.INFO)) {
            a.init("A");
            b.initAccepting("B");
            a.dns("B", 0);
            Wait.until("the pair's rate is known", () -> server.hub.snapshot().pairs().get(0).linkRateFirstToSecond() > 0);
            try (StatsLog stats = StatsLog.every(1, server.hub, true)) {
                Wait.until("a table logged", () -> !log.messages(Level.INFO).isEmpty());
            }
            String table = log.messages(Level.INFO).get(0);
            List<String> lines = table.lines().toList();
            assertEquals(6, lines.size(), table);
            assertEquals("link statistics, 1 pair", lines.get(0), table);
            assertEquals(StatsLog.SHAPED_HEADER, lines.get(1));
            // Noop's 0 dBm is above every step of the default table: its top rate, both ways.
            assertTrue(lines.get(2).matches("A - B +up +0 +- +0 +0 +0 +0 +54 Mbit/s +54 Mbit/s +0 +0 +0 +100\\.0 +-"), lines.get(2));
            assertEquals(StatsLog.AIRTIME_HEADER, lines.get(3));
            assertTrue(lines.get(4).matches("A +0 %"), lines.get(4));
            assertTrue(lines.get(5).matches("B +0 %"), lines.get(5));
        }
    }

    @Test
    void aShapedRowSaysTheRatesAndARobotLineItsAirtimeInWholePercent() {
        PairEntry pair = new PairEntry("Alpha", "Bravo", PairState.FORCED_UP, -80, 12.25, 1000, 2000, 10, 20, 3, 2, 1, 0.75,
                null, 1_500_000, 512_000);
        PairEntry unknown = new PairEntry("Alpha", "Charlie", PairState.BROKEN, -95, 40, 0, 0, 0, 0, 0, 1, 0, 0,
                "out of range", 0, 0);
        HubSnapshot snapshot = new HubSnapshot(List.of(new RobotEntry("Alpha", "127.0.0.1", List.of(), 0.374),
                new RobotEntry("Bravo", "127.0.0.1", List.of(), 1.0), new RobotEntry("Charlie", "127.0.0.1", List.of(), Double.NaN)),
                List.of(), List.of(), List.of(pair, unknown));
        List<String> lines = StatsLog.table(snapshot, true).lines().toList();
        assertEquals("link statistics, 2 pairs", lines.get(0));
        assertEquals(StatsLog.SHAPED_HEADER, lines.get(1));
        assertTrue(lines.get(2).matches("Alpha - Bravo +forced up +-80 +12\\.25 +1000 +2000 +10 +20 +1\\.5 Mbit/s +512 kbit/s +3 +2 +1 +75\\.0  -"),
                lines.get(2));
        assertTrue(lines.get(3).matches("Alpha - Charlie +broken +-95 +40 +0 +0 +0 +0 +- +- +0 +1 +0 +0\\.0  out of range"), lines.get(3));
        assertEquals(StatsLog.AIRTIME_HEADER, lines.get(4));
        assertEquals(List.of("Alpha                        37 %", "Bravo                       100 %"), lines.subList(5, 7),
                "a robot whose airtime is not known (NaN) has no line");
        // The rates line up under their headers.
        assertEquals(StatsLog.SHAPED_HEADER.indexOf("rate B>A") + "rate B>A".length(), lines.get(2).indexOf("512 kbit/s") + "512 kbit/s".length());
    }

    @Test
    void withoutShapingTheTableIsTheOneItAlwaysWasWhateverTheSnapshotSays() {
        PairEntry pair = new PairEntry("Alpha", "Bravo", PairState.UP, -80, 12.25, 1000, 2000, 10, 20, 3, 2, 1, 0.75, null);
        HubSnapshot snapshot = new HubSnapshot(List.of(new RobotEntry("Alpha", "127.0.0.1", List.of())), List.of(), List.of(),
                List.of(pair));
        String table = StatsLog.table(snapshot, false);
        assertEquals(StatsLog.table(List.of(pair)), table);
        assertEquals(List.of("link statistics, 1 pair", StatsLog.HEADER,
                "Alpha - Bravo            up               -80    12.25         1000         2000         10         20     3      2       1  75.0  -"),
                table.lines().toList());
    }

    @Test
    void whatTheModelDoesNotKnowIsADashNotNaN() {
        PairEntry pair = new PairEntry("Alpha", "Bravo", PairState.UP, Double.NaN, Double.NaN, 1, 2, 0, 0, 1, 0, 0, 1,
                null);
        String row = StatsLog.table(List.of(pair)).lines().toList().get(2);
        assertTrue(row.matches("Alpha - Bravo +up +- +- +1 +2 +0 +0 +1 +0 +0 +100\\.0  -"), row);
    }
}
