package org.usarsim.wss.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.PollingStub;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.recording.Recorder;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingReader;
import org.usarsim.wss.routes.RouteRule;
import org.usarsim.wss.routes.RouteTable;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * Issue 34, item 5: a replay shows the routes as they were. A run with links shaped is recorded
 * (a model that polls as the simulator models do), then replayed behind a hub shaped alike: at each
 * recorded poll, the same route table, rates and all. Routes are not recorded: they follow from the
 * recorded pairs' states and strengths (and the rates from those, by the same settings).
 */
class RouteReplayTest {

    private static final long MS = 1_000_000L;

    @TempDir
    Path dir;

    private static void poll(PollingStub model, List<ModelPoll.Pair> pairs) {
        List<ModelPoll.Robot> robots = new ArrayList<>();
        for (String name : List.of("A", "B", "C")) {
            robots.add(new ModelPoll.Robot(name, new Position(robots.size() * 10, 0, 0), false));
        }
        model.poll(robots, pairs);
    }

    private static ModelPoll.Pair pair(String a, String b, double dBm, boolean live) {
        return new ModelPoll.Pair(a, b, dBm, 0, live);
    }

    private static HubConfig shaped() throws Exception {
        return TestHub.config(true, 65536, 600, 1000, 30).withShaping(new ShapingConfig(true, RateTable.DEFAULT, 0, true), Map.of());
    }

    private static long relayed(double in, double out) {
        return RouteRule.relayBound(RateTable.DEFAULT.rateFor(in), RateTable.DEFAULT.rateFor(out));
    }

    @Test
    void aReplayHasTheRecordedRunsRoutesAtEachPoll() throws Exception {
        Path file = dir.resolve("run.rec");
        PollingStub model = new PollingStub();
        RouteTable first;
        RouteTable second;
        Recorder recorder = Recorder.create(file, model.name(), Map.of("wss.shaping", "on"));
        try (TestHub server = new TestHub(model, shaped())) {
            server.hub.addListener(recorder);
            recorder.started();
            try (TestRobot a = server.robot(); TestRobot b = server.robot(); TestRobot c = server.robot()) {
                a.init("A", 5001);
                b.init("B", 5002);
                c.init("C", 5003);
                poll(model, List.of(pair("A", "B", -50, true), pair("A", "C", -90, false), pair("B", "C", -75, true)));
                Wait.until("A to C through B, at its rate", () -> server.hub.routes().route("A", "C").rateBound() == relayed(-50, -75));
                first = server.hub.routes();
                poll(model, List.of(pair("A", "B", -50, true), pair("A", "C", -70, true), pair("B", "C", -95, false)));
                Wait.until("B to C through A", () -> server.hub.routes().route("B", "C").rateBound() == relayed(-50, -70));
                second = server.hub.routes();
            }
        } finally {
            recorder.close();
        }
        assertNotEquals(first, second);

        Recording recording = RecordingReader.read(file);
        assertEquals(2, recording.polls().size());
        AtomicLong now = new AtomicLong(0); // the replay at 0: its first poll applied
        ReplayPropagationModel replay = new ReplayPropagationModel(now::get);
        replay.configure(new ModelSettings(Map.of("replay.file", file.toString())));
        try (TestHub server = new TestHub(replay, shaped()); TestRobot a = server.robot(); TestRobot b = server.robot();
                TestRobot c = server.robot()) {
            a.init("A", 5001);
            b.init("B", 5002);
            c.init("C", 5003);
            RouteTable[] seen = new RouteTable[1];
            waitForTable(server, first, seen);
            now.set(recording.pollMillis(1) * MS);
            waitForTable(server, second, seen);
        }
    }

    private static void waitForTable(TestHub server, RouteTable expected, RouteTable[] seen) {
        try {
            Wait.until("the recorded routes", () -> expected.equals(seen[0] = server.hub.routes()));
        } catch (AssertionError e) {
            assertEquals(expected.all(), seen[0].all(), "the routes replayed");
            throw e;
        }
    }
}
