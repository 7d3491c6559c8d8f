package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.model.FakeReplay;

/**
 * The operator command REPLAY on the control port (docs/protocol.md section 8), over real sockets:
 * only from an address of wss.operators, with no INIT, to a model that replays (a fake replay
 * that records the calls); every refusal leaves the replay as it was and the connection usable.
 */
class ReplayCommandTest {

    private final ScriptedModel model = new ScriptedModel();
    private final FakeReplay replay = new FakeReplay(60);
    private TestHub server;

    @BeforeEach
    void start() throws Exception {
        model.replaying(replay);
        server = new TestHub(model, true, 65536);
    }

    @AfterEach
    void stop() {
        server.close();
    }

    @Test
    void anOperatorAsksJumpsChangesSpeedAndPausesWithoutINIT() throws Exception {
        try (TestRobot operator = server.robotAt("127.0.0.1")) {
            replay.time(12.3);
            assertEquals("REPLAYREPLY {Status OK} {Time 12.3} {Duration 60} {Speed 1} {State Play} {Poll 0}", operator.ask("REPLAY"),
                    "alone, it asks");
            assertEquals(List.of(), replay.calls());

            assertEquals("REPLAYREPLY {Status OK} {Time 30} {Duration 60} {Speed 1} {State Play} {Poll 0}", operator.ask("REPLAY {Time 30}"));
            assertEquals("REPLAYREPLY {Status OK} {Time 30} {Duration 60} {Speed 4} {State Play} {Poll 0}", operator.ask("REPLAY {Speed 4}"));
            assertEquals("REPLAYREPLY {Status OK} {Time 30} {Duration 60} {Speed 4} {State Pause} {Poll 0}", operator.ask("REPLAY {State pause}"));
            assertEquals("REPLAYREPLY {Status OK} {Time 0} {Duration 60} {Speed 0.25} {State Play} {Poll 0}",
                    operator.ask("REPLAY {State PLAY} {Time 0} {Speed 0.25}"), "all three in one line, any order, any case");
            assertEquals("REPLAYREPLY {Status OK} {Time 60} {Duration 60} {Speed 8} {State Play} {Poll 0}",
                    operator.ask("REPLAY{Time 60}{Speed 8}"), "the ends are in");
            assertEquals(List.of("jump 30.0", "speed 4.0", "pause", "speed 0.25", "jump 0.0", "play", "speed 8.0", "jump 60.0"),
                    replay.calls());

            operator.init("Station");
            assertEquals("REPLAYREPLY {Status OK} {Time 7.5} {Duration 60} {Speed 8} {State Play} {Poll 0}", operator.ask("REPLAY {Time 7.5}"),
                    "after INIT too");
        }
    }

    @Test
    void refusalsSayWhyChangeNothingAndTheSessionGoesOn() throws Exception {
        try (TestRobot operator = server.robotAt("127.0.0.1")) {
            String time = "ERROR {Reason Time.Must.Be.0.To.Duration.Seconds}";
            assertEquals(time, operator.ask("REPLAY {Time 60.001}"));
            assertEquals(time, operator.ask("REPLAY {Time -1}"));
            assertEquals(time, operator.ask("REPLAY {Time soon}"));
            assertEquals(time, operator.ask("REPLAY {Time NaN}"));
            assertEquals(time, operator.ask("REPLAY {Time}"));
            String speed = "ERROR {Reason Speed.Must.Be.0.25.To.8}";
            assertEquals(speed, operator.ask("REPLAY {Speed 0.2}"));
            assertEquals(speed, operator.ask("REPLAY {Speed 16}"));
            assertEquals(speed, operator.ask("REPLAY {Speed 2x}"));
            assertEquals(speed, operator.ask("REPLAY {Time 10} {Speed Infinity}"), "a bad field: the good one is not applied either");
            String state = "ERROR {Reason State.Must.Be.Pause.Or.Play}";
            assertEquals(state, operator.ask("REPLAY {State Stop}"));
            assertEquals(state, operator.ask("REPLAY {Time 10} {State}"));
            assertEquals(List.of(), replay.calls(), "nothing changed");
            assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", operator.ask("replay {Time 1}"), "the word is case-sensitive");
            assertEquals("REPLAYREPLY {Status OK} {Time 10} {Duration 60} {Speed 1} {State Play} {Poll 0}", operator.ask("REPLAY {Time 10}"),
                    "still usable");
        }
    }

    @Test
    void fromAForeignAddressItIsRefusedAndSaid() throws Exception {
        try (LogCapture warnings = LogCapture.of("org.usarsim.wss.hub.tcp.ControlSession", Level.WARNING);
                TestRobot foreign = server.robotAt("127.0.0.2")) {
            assertEquals("ERROR {Reason Not.An.Operator.Address}", foreign.ask("REPLAY {State Pause} {Poll 0}"));
            assertEquals("ERROR {Reason Not.An.Operator.Address}", foreign.ask("REPLAY"), "asking is an operator's too");
            assertEquals(List.of(), replay.calls());
            assertEquals(2, warnings.count(Level.WARNING, "REPLAY refused: 127.0.0.2 is not in wss.operators"), warnings.toString());
            foreign.init("R1");
            assertEquals("SS {Robot R1} {Strength INF} {Error SS.To.Self}", foreign.ask("GETSS {Robot R1}"), "still usable");
        }
    }

    @Test
    void aModelThatReplaysNothingSaysSo() throws Exception {
        model.replaying(null);
        try (TestRobot operator = server.robotAt("127.0.0.1")) {
            assertEquals("ERROR {Reason Not.A.Replay}", operator.ask("REPLAY"));
            assertEquals("ERROR {Reason Not.A.Replay}", operator.ask("REPLAY {Time 10}"), "before the fields are looked at");
            model.replaying(replay);
            assertEquals("REPLAYREPLY {Status OK} {Time 0} {Duration 60} {Speed 1} {State Play} {Poll 0}", operator.ask("REPLAY"));
        }
    }
}
