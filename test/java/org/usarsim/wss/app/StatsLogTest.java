package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.logging.Level;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.PairState;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;

/** wss.statsInterval: the whole statistics table in the headless log, every so many seconds. */
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
    void whatTheModelDoesNotKnowIsADashNotNaN() {
        PairEntry pair = new PairEntry("Alpha", "Bravo", PairState.UP, Double.NaN, Double.NaN, 1, 2, 0, 0, 1, 0, 0, 1,
                null);
        String row = StatsLog.table(List.of(pair)).lines().toList().get(2);
        assertTrue(row.matches("Alpha - Bravo +up +- +- +1 +2 +0 +0 +1 +0 +0 +100\\.0  -"), row);
    }
}
