package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.logging.Level;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.net.LogLimiter;
import org.usarsim.wss.protocol.Arguments;

/**
 * An operator's FORCEs cannot fill the disk (issue 19): 200 FORCEs with 256-character names (the longest; issue 27) from one
 * connection write at most the first few of each kind of line a minute, every FORCE still answered.
 */
class ForceLogLimitTest {

    @Test
    void manyForcesWriteAFewLinesAndEveryOneIsAnswered() throws Exception {
        String longName = "R".repeat(Arguments.MAX_NAME - 3); // the longest a name may be, with its number

        try (LogCapture session = LogCapture.of("org.usarsim.wss.hub.tcp.ControlSession", Level.INFO);
                LogCapture events = LogCapture.of("org.usarsim.wss.events", Level.INFO);
                TestHub server = new TestHub();
                TestRobot operator = server.robot()) {
            for (int i = 0; i < 200; i++) {
                String state = i % 2 == 0 ? "Down" : "Up";
                assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot " + longName + String.format("%03d", i) + "} {Peer B} {State " + state + "}"));
            }
            long operatorLines = session.count(Level.INFO, "FORCE");
            long forcedLines = events.count(Level.INFO, "forced ");
            assertEquals(LogLimiter.FIRST, operatorLines, "the operator's own lines: the first few from its address");
            assertTrue(forcedLines <= LogLimiter.ALL_FIRST, forcedLines + " 'forced' lines for 200 forces");
            assertTrue(session.messages(Level.INFO).stream().allMatch(line -> line.length() <= LogLimiter.MAX_MESSAGE + 100),
                    "a long name is cut");
        }
    }
}
