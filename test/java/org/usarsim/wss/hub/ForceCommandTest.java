package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.net.ConnectException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Map;
import java.util.Set;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.model.RobotPair;

/**
 * The operator command on the control port (docs/protocol.md section 7): FORCE, only from an
 * address of wss.operators (127.0.0.1 by default), with no INIT; robots' answers unchanged.
 */
class ForceCommandTest {

    private static final String OK = "FORCEREPLY {Status OK}";
    private static final RobotPair PAIR = RobotPair.of("R1", "R2");

    private TestHub server;

    @BeforeEach
    void start() throws Exception {
        server = new TestHub(new ScriptedModel(), true, 65536);
    }

    @AfterEach
    void stop() {
        server.close();
    }

    @Test
    void fromAForeignAddressFORCEIsRefusedWithAClearErrorAndChangesNothing() throws Exception {
        try (LogCapture warnings = LogCapture.of("org.usarsim.wss.hub.tcp.ControlSession", Level.WARNING);
                TestRobot foreign = server.robotAt("127.0.0.2")) {
            assertEquals("ERROR {Reason Not.An.Operator.Address}", foreign.ask("FORCE {Robot R1} {Peer R2} {State Down}"),
                    "before INIT");
            foreign.init("R1", 5000);
            assertEquals("ERROR {Reason Not.An.Operator.Address}", foreign.ask("FORCE {Robot R1} {Peer R2} {State Up}"),
                    "a registered robot is no operator either");
            assertEquals("ERROR {Reason Not.An.Operator.Address}", foreign.ask("FORCE {State Model}"),
                    "the address is checked first");
            assertNull(server.hub.forced(PAIR));
            assertEquals(3, warnings.count(Level.WARNING, "FORCE refused: 127.0.0.2 is not in wss.operators"), warnings.toString());
            assertEquals("SS {Robot R1} {Strength INF} {Error SS.To.Self}", foreign.ask("GETSS {Robot R1}"), "still usable");
        }
    }

    @Test
    void aJitterInFORCEIsWholeMillisecondsFrom0To10000AndNeedsStateUp() throws Exception {
        try (TestRobot operator = server.robotAt("127.0.0.1")) {
            String jitter = "ERROR {Reason Jitter.Must.Be.0.To.10000.Ms}";
            assertEquals(jitter, operator.ask("FORCE {Robot R1} {Peer R2} {State Up} {Jitter 10001}"));
            assertEquals(jitter, operator.ask("FORCE {Robot R1} {Peer R2} {State Up} {Jitter -1}"));
            assertEquals(jitter, operator.ask("FORCE {Robot R1} {Peer R2} {State Up} {Jitter 2.5}"));
            assertEquals(jitter, operator.ask("FORCE {Robot R1} {Peer R2} {State Up} {Rate 1M} {Jitter lots}"));
            assertEquals("ERROR {Reason Rate.And.Delay.Need.State.Up}", operator.ask("FORCE {Robot R1} {Peer R2} {State Down} {Jitter 5}"));
            assertEquals("ERROR {Reason Rate.And.Delay.Need.State.Up}", operator.ask("FORCE {Robot R1} {Peer R2} {State Model} {Jitter 5}"));
            assertNull(server.hub.forced(PAIR), "nothing refused changed anything");
            assertEquals(OK, operator.ask("FORCE {Robot R1} {Peer R2} {State Up} {Jitter 0}"));
            assertEquals(OK, operator.ask("FORCE {Robot R1} {Peer R2} {State Up} {Rate 1M} {Delay 50} {Jitter 10000}"));
            assertEquals(Force.UP, server.hub.forced(PAIR));
        }
    }

    @Test
    void fromTheOperatorAddressFORCEWorksWithoutINITAndForcesTheRealPorts() throws Exception {
        try (TestRobot operator = server.robotAt("127.0.0.1"); TestRobot r1 = server.robotAt("127.0.0.1");
                TestRobot r2 = server.robotAt("127.0.0.3")) {
            ServerSocket r2Accepts = r2.initAccepting("R2");
            r1.init("R1");
            int toR2 = r1.dns("R2", 0);

            assertEquals(OK, operator.ask("FORCE {Robot R2} {Peer R1} {State Down}"));
            assertEquals(Force.DOWN, server.hub.forced(PAIR));
            assertThrows(ConnectException.class, () -> r1.connect(toR2).close(), "forced down over the control port");

            assertEquals(OK, operator.ask("FORCE {Robot R1} {Peer R2} {State model}"), "the state in any case");
            assertNull(server.hub.forced(PAIR));
            try (Socket out = r1.connect(toR2); Socket in = r2Accepts.accept()) {
                out.getOutputStream().write('!');
                assertEquals('!', in.getInputStream().read(), "released: the model allows the pair");
            }
            assertEquals(OK, operator.ask("FORCE{Robot R1}{Peer R2}{State UP}"));
            assertEquals(Force.UP, server.hub.forced(PAIR));
            assertEquals(OK, operator.ask("FORCE {Robot Later1} {Peer Later2} {State Down}"), "robots not registered: ahead of time");
            assertEquals(Force.DOWN, server.hub.forced(RobotPair.of("Later1", "Later2")));

            // The operator's connection is no robot: it may still register as one.
            assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", operator.ask("GETSS {Robot R1}"));
            operator.init("Station");
            assertEquals(OK, operator.ask("FORCE {Robot R1} {Peer R2} {State Model}"), "after INIT too");
        }
    }

    @Test
    void badFORCECommandsGetTheirReasonAndNoSegmentIsAnUnknownMethodAsTheOriginal() throws Exception {
        try (TestRobot operator = server.robotAt("127.0.0.1")) {
            assertEquals("ERROR {Reason Robot.Name.Must.Not.Be.Empty}", operator.ask("FORCE {Peer R2} {State Down}"));
            assertEquals("ERROR {Reason Robot.Name.Must.Not.Contain.Whitespace}", operator.ask("FORCE {Robot R 1} {Peer R2} {State Down}"));
            assertEquals("ERROR {Reason Peer.Name.Must.Not.Be.Empty}", operator.ask("FORCE {Robot R1} {Peer} {State Down}"));
            assertEquals("ERROR {Reason Peer.Name.Must.Not.Contain.Whitespace}", operator.ask("FORCE {Robot R1} {Peer R 2} {State Down}"));
            assertEquals("ERROR {Reason Peer.Must.Not.Be.The.Robot}", operator.ask("FORCE {Robot R1} {Peer R1} {State Down}"));
            assertEquals("ERROR {Reason State.Must.Be.Down.Up.Or.Model}", operator.ask("FORCE {Robot R1} {Peer R2}"));
            assertEquals("ERROR {Reason State.Must.Be.Down.Up.Or.Model}", operator.ask("FORCE {Robot R1} {Peer R2} {State Off}"));
            assertNull(server.hub.forced(PAIR));
            assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", operator.ask("FORCE"), "no segment, before INIT");
            assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", operator.ask("force {Robot R1} {Peer R2} {State Down}"),
                    "the word is case-sensitive");
            operator.init("R9");
            assertEquals("ERROR {Reason Method.Unknown.Or.Can.INIT.only.once}", operator.ask("FORCE  "), "no segment, after INIT");
        }
    }

    @Test
    void wssOperatorsNamesWhoMayForce() throws Exception {
        HubConfig base = TestHub.config(true, 65536, 600, 1000, 30);
        HubConfig config = new HubConfig(base.bindAddress(), 0, base.chunkSize(), base.socketBuffer(), true, 600, 1000,
                base.maxPortsPerAddress(), 30, Set.of(InetAddress.getByName("127.0.0.2")), Map.of(), Map.of(), base.shaping(), base.fixed());
        try (TestHub other = new TestHub(new ScriptedModel(), config); TestRobot local = other.robotAt("127.0.0.1");
                TestRobot second = other.robotAt("127.0.0.2")) {
            assertEquals("ERROR {Reason Not.An.Operator.Address}", local.ask("FORCE {Robot A} {Peer B} {State Down}"),
                    "127.0.0.1 is not in this wss.operators");
            assertEquals(OK, second.ask("FORCE {Robot A} {Peer B} {State Down}"));
            assertEquals(Force.DOWN, other.hub.forced(RobotPair.of("A", "B")));
        }
    }
}
