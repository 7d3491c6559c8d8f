package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.net.ServerSocket;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Lines where a comparison with the original server found a different answer by accident: each
 * now gets the original's exact reply, over a real socket (docs/protocol.md, sections 1 to 3).
 */
class OriginalRepliesTest {

    private static final String MUST_INIT_FIRST = "ERROR {Reason Must.Use.INIT.Method.First}";
    private static final String UNKNOWN = "ERROR {Reason Method.Unknown.Or.Can.INIT.only.once}";

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
    void initWithNoSegmentBeforeInitMustUseInitFirst() throws Exception {
        try (TestRobot robot = server.robot()) {
            assertEquals(MUST_INIT_FIRST, robot.ask("INIT"));
            assertEquals(MUST_INIT_FIRST, robot.ask("INIT   "));
            assertEquals("ERROR {Reason Robot.Name.Must.Not.Be.Empty}", robot.ask("INIT {Port 5000}"), "a segment: the INIT checks");
            robot.init("R1", 5000);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"GETSS", "DNS", "REVERSEDNS", "INIT", "GETSS  "})
    void aCommandWithNoSegmentAfterInitIsAnUnknownMethod(String line) throws Exception {
        try (TestRobot robot = server.robot(); TestRobot other = server.robot()) {
            robot.init("R1", 5000);
            other.init("R2", 6000);
            assertEquals(UNKNOWN, robot.ask(line));
            assertEquals("SS {Robot R2} {Strength 0}", robot.ask("GETSS {Robot R2}"));
        }
    }

    @Test
    void aKeyGivenTwiceTheLastOneCounts() throws Exception {
        try (TestRobot q = server.robot(); TestRobot a = server.robot(); TestRobot b = server.robot()) {
            ServerSocket first = a.listen();
            ServerSocket second = a.listen();
            assertEquals("INITREPLY {Status OK}", q.ask("INIT {Robot Q2} {Robot Q3} {Port 5000}"));
            assertEquals(List.of("Q3"), server.hub.getListOfRegisteredRobots(), "registers Q3");
            assertEquals("INITREPLY {Status OK}",
                    a.ask("INIT {Robot A} {Port " + first.getLocalPort() + "," + second.getLocalPort() + "}"));
            b.init("B");
            assertEquals("SS {Robot B} {Strength 0}", q.ask("GETSS {Robot A} {Robot B}"));
            assertEquals("SS {Robot Q3} {Strength INF} {Error SS.To.Self}", q.ask("GETSS {Robot A} {Robot Q3}"));
            int wssPort = b.dns("A", second.getLocalPort());
            assertEquals("DNSREPLY {Robot A} {Port " + wssPort + "}",
                    b.ask("DNS {Robot A} {Port " + first.getLocalPort() + "} {Port " + second.getLocalPort() + "}"),
                    "asks for the second port");
            assertEquals("DNSREPLY {Robot A} {Port -1} {Error RobotDoesNotListenOnThisPort}",
                    b.ask("DNS {Robot A} {Port " + first.getLocalPort() + "} {Port 5001}"));
            try (java.net.Socket data = b.connect(wssPort); java.net.Socket accepted = second.accept()) {
                data.getOutputStream().write('x');
                assertEquals('x', accepted.getInputStream().read(), "forwarded to the last port asked");
            }
        }
    }

    @Test
    void dnsWithAnEmptyPortValueIsNotAnInteger() throws Exception {
        try (TestRobot robot = server.robot(); TestRobot x = server.robot()) {
            robot.init("R1", 5000);
            x.init("X", 6000);
            assertEquals("ERROR {Reason Port.Must.Be.Integer}", robot.ask("DNS {Robot X} {Port }"));
            assertEquals("ERROR {Reason Port.Must.Be.Integer}", robot.ask("DNS {Robot X} {Port}"));
            assertEquals("ERROR {Reason Port.Must.Be.Integer}", robot.ask("DNS {Robot X} {Port 9999999999}"));
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"0", "-1", "70000", "5000,0", "2147483647", "0,5000"})
    void initAcceptsAnyIntegerPortAndDnsNeverDialsAnInvalidOne(String list) throws Exception {
        try (TestRobot p = server.robot(); TestRobot asker = server.robot()) {
            assertEquals("INITREPLY {Status OK}", p.ask("INIT {Robot P} {Port " + list + "}"));
            asker.init("A", 6000);
            assertEquals(List.of("A", "P"), server.hub.getListOfRegisteredRobots());
            for (String port : list.split(",")) {
                String reply = asker.ask("DNS {Robot P} {Port " + port + "}");
                if (port.equals("5000")) {
                    assertEquals("DNSREPLY {Robot P} {Port " + asker.dns("P", 5000) + "}", reply);
                } else if (!port.equals("0")) {
                    assertEquals("DNSREPLY {Robot P} {Port -1} {Error RobotDoesNotListenOnThisPort}", reply);
                }
            }
            String first = list.split(",")[0];
            String noPort = asker.ask("DNS {Robot P}");
            assertEquals(noPort, asker.ask("DNS {Robot P} {Port 0}"), "{Port 0} is the first port");
            if (first.equals("5000")) {
                assertEquals("DNSREPLY {Robot P} {Port " + asker.dns("P", 5000) + "}", noPort);
            } else {
                assertEquals("DNSREPLY {Robot P} {Port -1} {Error RobotDoesNotListenOnThisPort}", noPort,
                        "the first listed port is not 1..65535");
            }
            assertEquals("DNSREPLY {Robot P} {Port -1} {Error RobotDoesNotListenOnThisPort}", asker.ask("DNS {Robot P} {Port -1}"));
            assertEquals("DNSREPLY {Robot Nobody} {Port -1} {Error NoSuchRobot}", asker.ask("DNS {Robot Nobody} {Port 70000}"));
        }
    }
}
