package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The control protocol over a real socket, as real clients use it. */
class ControlSessionTest {

    private TestHub server;

    @BeforeEach
    void start() throws Exception {
        server = new TestHub();
    }

    @AfterEach
    void stop() {
        server.close();
    }

    @Test
    void everyCommandBeforeInitIsRefused() throws Exception {
        try (TestRobot robot = server.robot()) {
            assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", robot.ask("GETSS {Robot R2}"));
            assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", robot.ask("DNS {Robot R2}"));
            assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", robot.ask("REVERSEDNS {Port 5}"));
            assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", robot.ask("HELLO"));
            assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", robot.ask("init {Robot R1}"));
            robot.init("R1", 5000);
        }
    }

    @Test
    void initWithAPortListRegistersEveryPort() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            assertEquals("INITREPLY {Status OK}", r1.ask("INIT {Robot R1} {Port 5000,5001}"));
            assertEquals("INITREPLY {Status OK}", r2.ask("INIT {Robot R2} {Port 6000, 6001}"));
            r2.dns("R1", 5000);
            r2.dns("R1", 5001);
            r1.dns("R2", 6001);
            assertEquals("DNSREPLY {Robot R1} {Port -1} {Error RobotDoesNotListenOnThisPort}", r2.ask("DNS {Robot R1} {Port 5002}"));
            assertEquals(r2.dns("R1", 5000), r2.dns("R1", 0), "no port means the first registered");
            assertEquals(r2.dns("R1", 5000), r2.dns("R1", 0));
            assertEquals(java.util.List.of("R1", "R2"), server.hub.getListOfRegisteredRobots());
        }
    }

    @Test
    void badInitsAreAnsweredAndChangeNothing() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot other = server.robot()) {
            assertEquals("ERROR {Reason Ports.List.Must.Be.Integer}", r1.ask("INIT {Robot R1} {Port 50a0}"));
            assertEquals("ERROR {Reason Ports.List.Must.Be.Integer}", r1.ask("INIT {Robot R1} {Port 5000,,5001}"));
            assertEquals("ERROR {Reason Robot.Name.Must.Not.Be.Empty}", r1.ask("INIT {Port 5000}"));
            assertEquals("ERROR {Reason Robot.Name.Must.Not.Be.Empty}", r1.ask("INIT {Robot} {Port 5000}"));
            r1.init("R1", 5000);
            assertEquals("ERROR {Reason Method.Unknown.Or.Can.INIT.only.once}", r1.ask("INIT {Robot R9} {Port 5000}"));
            assertEquals("ERROR {Reason Robot.Alread.Exists}", other.ask("INIT {Robot R1} {Port 6000}"));
        }
    }

    @Test
    void aFailedInitOfATakenNameDoesNotDeregisterTheRealRobot() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            r1.init("R1", 5000);
            r2.init("R2", 6000);
            try (TestRobot impostor = server.robot()) {
                assertEquals("ERROR {Reason Robot.Alread.Exists}", impostor.ask("INIT {Robot R1} {Port 7000}"));
            }
            // The impostor's connection is closed; R1 must still be registered.
            assertEquals("SS {Robot R1} {Strength 0}", r2.ask("GETSS {Robot R1}"));
            r2.dns("R1", 0);
        }
    }

    @Test
    void getSignalStrength() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            r1.init("R1", 5000);
            r2.init("XR1", 5000);
            assertEquals("SS {Robot XR1} {Strength 0}", r1.ask("GETSS {Robot XR1}"));
            assertEquals("SS {Robot R1} {Strength INF} {Error SS.To.Self}", r1.ask("GETSS {Robot R1}"));
            assertEquals("SS {Robot X} {Strength NaN} {Error Robot.Does.Not.Exist}", r1.ask("GETSS {Robot X}"));
            assertEquals("SS {Robot XR} {Strength NaN} {Error Robot.Does.Not.Exist}", r1.ask("GETSS {Robot XR}"), "exact names");
            assertEquals("ERROR {Reason Method.Unknown.Or.Can.INIT.only.once}", r1.ask("GETSS"));
            assertEquals("ERROR {Reason Robot.Name.Must.Not.Be.Empty}", r1.ask("GETSS {Robot }"));
        }
    }

    @Test
    void dnsErrors() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); TestRobot mute = server.robot()) {
            r1.init("R1", 5000);
            r2.init("R2", 6000);
            mute.init("Mute");
            assertEquals("DNSREPLY {Robot R1} {Port -1} {Error NoSuchRobot}", r1.ask("DNS {Robot R1}"));
            assertEquals("DNSREPLY {Robot Nobody} {Port -1} {Error NoSuchRobot}", r1.ask("DNS {Robot Nobody}"));
            assertEquals("DNSREPLY {Robot R2} {Port -1} {Error RobotDoesNotListenOnThisPort}", r1.ask("DNS {Robot R2} {Port 6001}"));
            assertEquals("DNSREPLY {Robot Mute} {Port -1} {Error RobotDoesNotListenOnThisPort}", r1.ask("DNS {Robot Mute}"));
            assertEquals("ERROR {Reason Port.Must.Be.Integer}", r1.ask("DNS {Robot R2} {Port six}"));
            assertEquals("ERROR {Reason Robot.Name.Must.Not.Be.Empty}", r1.ask("DNS {Port 6000}"));
            assertEquals("ERROR {Reason Port.Must.Be.Integer}", r1.ask("REVERSEDNS {Port x}"));
            assertEquals("ERROR {Reason Port.Must.Be.Integer}", r1.ask("REVERSEDNS {Robot R2}"));
            assertEquals("REVERSEDNSREPLY {Port 1234} {Error UnknownOrIllegalPort}", r1.ask("REVERSEDNS {Port 1234}"));
            assertEquals("ERROR {Reason Method.Unknown.Or.Can.INIT.only.once}", r1.ask("FLY {To Moon}"));
        }
    }

    @Test
    void pipelinedBurstIsAnsweredInOrder() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            r1.init("R1", 5000);
            r2.init("R2", 6000);
            StringBuilder burst = new StringBuilder();
            for (int i = 0; i < 200; i++) {
                burst.append(i % 2 == 0 ? "GETSS {Robot R2}\r\n" : "GETSS {Robot Ghost" + i + "}\r\n");
            }
            r1.send(burst.toString());
            for (int i = 0; i < 200; i++) {
                String expected = i % 2 == 0 ? "SS {Robot R2} {Strength 0}"
                        : "SS {Robot Ghost" + i + "} {Strength NaN} {Error Robot.Does.Not.Exist}";
                assertEquals(expected, r1.readLine());
            }
        }
    }

    @Test
    void linesSplitAcrossWritesAndBareLineFeeds() throws Exception {
        try (TestRobot r1 = server.robot()) {
            r1.send("IN");
            r1.send("IT {Robot R1} ");
            r1.send("{Port 5000}\r");
            r1.send("\nGETSS {Robot R1}\n\r\n   \n\nGETSS   {Robot   R1 }{Port 7}\n");
            assertEquals("INITREPLY {Status OK}", r1.readLine());
            assertEquals("SS {Robot R1} {Strength INF} {Error SS.To.Self}", r1.readLine());
            assertEquals("SS {Robot R1} {Strength INF} {Error SS.To.Self}", r1.readLine());
        }
    }

    @Test
    void oneWholeReplyPerRead() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            r1.init("R1", 5000);
            r2.init("R2", 6000);
            InputStream in = r1.control.getInputStream();
            byte[] buffer = new byte[1024];
            for (String command : new String[] {"GETSS {Robot R2}", "DNS {Robot R2}", "GETSS {Robot R1}", "BOGUS"}) {
                r1.send(command + "\r\n");
                int read = in.read(buffer);
                String reply = new String(buffer, 0, read, StandardCharsets.UTF_8);
                assertTrue(reply.endsWith("\r\n") && reply.indexOf('\n') == reply.length() - 1,
                        "one whole reply in one read: '" + reply + "'");
            }
        }
    }

    @Test
    void malformedLinesGetAnErrorAndTheConnectionStaysUsable() throws Exception {
        try (TestRobot r1 = server.robot()) {
            assertEquals("ERROR {Reason Malformed.Line.Unclosed.Brace}", r1.ask("INIT {Robot R1"));
            assertEquals("ERROR {Reason Malformed.Line.Text.Outside.Braces}", r1.ask("INIT Robot R1"));
            assertEquals("ERROR {Reason Malformed.Line.No.Command}", r1.ask("{Robot R1}"));
            assertEquals("ERROR {Reason Malformed.Line.Nested.Brace}", r1.ask("INIT {Robot {R1}}"));
            assertEquals("ERROR {Reason Malformed.Line.Empty.Segment}", r1.ask("INIT {} {Robot R1}"));
            r1.init("R1", 5000);
            assertEquals("ERROR {Reason Malformed.Line.Unclosed.Brace}", r1.ask("GETSS {Robot R1"));
            assertEquals("SS {Robot R1} {Strength INF} {Error SS.To.Self}", r1.ask("GETSS {Robot R1}"));
        }
    }

    @Test
    void anOverlongLineGetsAnErrorAndTheConnectionStaysUsable() throws Exception {
        try (TestRobot r1 = server.robot()) {
            r1.init("R1", 5000);
            String huge = "GETSS {Robot " + "x".repeat(200 * 1024) + "}\r\n";
            r1.send(huge + "GETSS {Robot R1}\r\n");
            assertEquals("ERROR {Reason Line.Too.Long}", r1.readLine());
            assertEquals("SS {Robot R1} {Strength INF} {Error SS.To.Self}", r1.readLine());
            String justFits = "GETSS {Robot " + "y".repeat(65536 - "GETSS {Robot }".length()) + "}";
            assertEquals(65536, justFits.length());
            assertEquals("ERROR {Reason Robot.Name.Must.Be.At.Most.256.Characters}", r1.ask(justFits),
                    "a line that fits is read whole: its name is what is refused (issue 27)");
            r1.send("z".repeat(65537));
            assertEquals("ERROR {Reason Line.Too.Long}", r1.readLine(), "at the 65,537th byte, no line end needed");
            r1.send("\n");
            assertEquals("SS {Robot R1} {Strength INF} {Error SS.To.Self}", r1.ask("GETSS {Robot R1}"));
        }
    }

    @Test
    void aLineOfControlWhitespaceOnlyGetsOneReplyAndASpacesOnlyLineNone() throws Exception {
        try (TestRobot r1 = server.robot()) {
            r1.send("   \r\n\n\t\r\n");
            assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", r1.readLine());
            r1.init("R1", 5000);
            r1.send("\u000B\f\n\u001C\u001D\u001E\u001F\r\n \r\r\n");
            for (int i = 0; i < 3; i++) {
                assertEquals("ERROR {Reason Method.Unknown.Or.Can.INIT.only.once}", r1.readLine());
            }
            assertEquals("SS {Robot R1} {Strength INF} {Error SS.To.Self}", r1.ask("GETSS {Robot R1}"), "nothing else came");
        }
    }

    @Test
    void aRobotThatLosesItsControlConnectionCanRegisterAgainAtOnce() throws Exception {
        try (TestRobot r2 = server.robot()) {
            r2.init("R2", 6000);
            for (int i = 0; i < 20; i++) {
                TestRobot r1 = server.robot();
                r1.init("R1", 5000);
                r1.close();
                try (TestRobot again = server.robot()) {
                    again.init("R1", 5000);
                    assertEquals("SS {Robot R1} {Strength 0}", r2.ask("GETSS {Robot R1}"));
                }
            }
        }
    }
}
