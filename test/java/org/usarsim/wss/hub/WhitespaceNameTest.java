package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * A robot name with whitespace inside, over a real socket: the original answers
 * {@code Robot.Name.Must.Not.Be.Empty}, which is not what is wrong; this server names the
 * whitespace (docs/protocol.md section 6), and the robot can go on with a good name.
 */
class WhitespaceNameTest {

    private static final String WHITESPACE = "ERROR {Reason Robot.Name.Must.Not.Contain.Whitespace}";

    @Test
    void initAndGetssWithASpaceInsideTheNameSayWhitespaceNotEmpty() throws Exception {
        try (TestHub server = new TestHub(); TestRobot w = server.robot(); TestRobot s = server.robot()) {
            assertEquals(WHITESPACE, w.ask("INIT {Robot W 1} {Port 5000}"));
            assertEquals(WHITESPACE, w.ask("INIT {Robot W\t1} {Port 5000}"), "a tab is whitespace too");
            w.init("W1", 5000);
            s.init("s1", 6000);
            assertEquals(WHITESPACE, w.ask("GETSS {Robot s1 AB}"));
            assertEquals(WHITESPACE, w.ask("DNS {Robot s1 AB}"));
            assertEquals("SS {Robot s1} {Strength 0}", w.ask("GETSS {Robot s1}"), "the connection goes on");
        }
    }
}
