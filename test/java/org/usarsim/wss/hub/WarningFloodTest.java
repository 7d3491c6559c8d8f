package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.List;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/**
 * One client against the log: connects the server refuses and over-long lines, each a WARNING,
 * sent over and over. The first few of each kind are written, the rest said in one line, and
 * the server goes on answering everyone.
 */
class WarningFloodTest {

    private static final int FLOOD = 40;

    /** The hub's clock: no interval ends unless a test moves it. */
    private final ManualHubClock clock = new ManualHubClock();
    private TestHub server;
    private LogCapture log;

    @BeforeEach
    void start() throws Exception {
        log = LogCapture.of("org.usarsim.wss.hub", Level.INFO);
        server = new TestHub(new NoopPropagationModel(), TestHub.config(true, 65536, 600, 1000, 30), clock);
    }

    @AfterEach
    void stop() {
        server.close();
        log.close();
    }

    @Test
    void refusedConnectsFromOneAddressWriteFiveWarningsThenOneLineSayingHowManyMore() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); TestRobot intruder = server.robotAt("127.0.0.3")) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            int port = r2.dns("R1", 0);
            // R2 registered from 127.0.0.1: a connection to its port from 127.0.0.3 is refused.
            refusedConnects(intruder, port, FLOOD);
            assertEquals(WarningLimiter.FIRST, log.count(Level.WARNING, "refused a connection"), log.toString());
            try (Socket fromR2 = r2.connect(port); Socket atR1 = r1Accepts.accept()) {
                fromR2.getOutputStream().write('x');
                assertEquals('x', atR1.getInputStream().read(), "R2 is still forwarded");
            }
            assertEquals("SS {Robot R1} {Strength 0}", r2.ask("GETSS {Robot R1}"));
        }
        server.close();
        assertEquals(List.of("refused connections: " + (FLOOD - WarningLimiter.FIRST) + " more like this from 127.0.0.3 in the last S s"),
                summaries(), "said when the server stops, before the interval ends");
    }

    @Test
    void overLongLinesFromOneAddressWriteFiveWarningsThenOneLineAndEveryLineIsAnswered() throws Exception {
        try (TestRobot flooder = server.robotAt("127.0.0.4"); TestRobot other = server.robot()) {
            flooder.init("F");
            other.init("O");
            String huge = "GETSS {Robot " + "x".repeat(70 * 1024) + "}\r\n";
            for (int i = 0; i < FLOOD; i++) {
                flooder.send(huge);
                assertEquals("ERROR {Reason Line.Too.Long}", flooder.readLine(), "line " + i);
            }
            assertEquals(WarningLimiter.FIRST, log.count(Level.WARNING, "a control line longer than"), log.toString());
            assertEquals("SS {Robot O} {Strength 0}", flooder.ask("GETSS {Robot O}"));
            assertEquals("SS {Robot F} {Strength 0}", other.ask("GETSS {Robot F}"));
            // Another address has a limit of its own.
            other.send(huge);
            assertEquals("ERROR {Reason Line.Too.Long}", other.readLine());
            assertEquals(WarningLimiter.FIRST + 1, log.count(Level.WARNING, "a control line longer than"));
        }
        server.close();
        assertEquals(List.of("over-long lines: " + (FLOOD - WarningLimiter.FIRST) + " more like this from 127.0.0.4 in the last S s"),
                summaries());
    }

    @Test
    void aTargetThatDoesNotAcceptIsWarnedAboutFiveTimesPerSource() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robotAt("127.0.0.2")) {
            ServerSocket closed = r1.listen();
            int deadPort = closed.getLocalPort();
            closed.close();
            r1.init("R1", deadPort);
            r2.init("R2");
            int port = r2.dns("R1", 0);
            for (int i = 0; i < FLOOD / 4; i++) {
                try (Socket socket = r2.connect(port)) {
                    Sockets.assertClosedByPeer(socket, "connection " + i + " to a target that does not accept");
                }
            }
            Wait.until("every link ended", () -> Sockets.linkThreads() == 0);
            assertEquals(WarningLimiter.FIRST, log.count(Level.WARNING, "did not accept"), log.toString());
        }
        server.close();
        assertEquals(List.of("unreachable targets: " + (FLOOD / 4 - WarningLimiter.FIRST) + " more like this from 127.0.0.2 in the last S s"),
                summaries());
    }

    /**
     * The limit's interval is on the hub's clock: once it has moved a minute on, the summary is
     * said by the timer, and the next refused connect is written again.
     */
    @Test
    void theSummaryIsSaidWhenTheHubsClockEndsTheIntervalAndTheNextWarningIsWrittenAgain() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); TestRobot intruder = server.robotAt("127.0.0.3")) {
            r1.initAccepting("R1");
            r2.init("R2", 6000);
            int port = r2.dns("R1", 0);
            refusedConnects(intruder, port, FLOOD);
            assertEquals(WarningLimiter.FIRST, log.count(Level.WARNING, "refused a connection"), log.toString());
            assertEquals(List.of(), summaries(), "the interval has not ended");

            clock.advance(Duration.ofSeconds(60));
            Wait.until("the summary, said by the warnings' timer", () -> summaries().size() == 1);
            assertEquals("refused connections: " + (FLOOD - WarningLimiter.FIRST) + " more like this from 127.0.0.3 in the last 60 s",
                    log.messages(Level.WARNING).stream().filter(m -> m.contains(" more like this from ")).findFirst().orElseThrow());
            refusedConnects(intruder, port, 1);
            Wait.until("the new interval's first refusal written", () -> log.count(Level.WARNING, "refused a connection") == WarningLimiter.FIRST + 1);
        }
    }

    /** {@code count} connections of {@code from} to the WSS port, each refused (closed at once). */
    private static void refusedConnects(TestRobot from, int port, int count) throws Exception {
        for (int i = 0; i < count; i++) {
            try (Socket socket = from.connect(port)) {
                Sockets.assertClosedByPeer(socket, "refused connection " + i);
            }
        }
    }

    /** The summary lines, the seconds they name replaced by S (the flood takes a moment of its own). */
    private List<String> summaries() {
        return log.messages(Level.WARNING).stream().filter(m -> m.contains(" more like this from "))
                .map(m -> m.replaceAll("in the last \\d+ s$", "in the last S s")).toList();
    }
}
