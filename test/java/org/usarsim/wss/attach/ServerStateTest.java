package org.usarsim.wss.attach;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.JsonNode;

/** The monitor's snapshot and events (docs/monitor.md) applied to what an attached window shows. */
class ServerStateTest {

    private static final String STATE = """
            {"run":"5f1c0a9e","lastEventId":"5f1c0a9e-3","operator":false,
             "server":{"version":"1","bindAddress":"127.0.0.1","controlPort":50000},
             "model":{"name":"DistanceOnly","settings":{},"cutoff":30.0,"walls":[{"x1":0,"y1":0,"x2":5,"y2":0}]},
             "replay":null,
             "robots":[{"name":"r2","address":"127.0.0.1","ports":[5001],"airtime":null,"position":null,"range":null},
                       {"name":"r1","address":"127.0.0.1","ports":[5000],"airtime":null,"position":{"x":1,"y":2,"z":0},"range":30.0}],
             "ports":[{"from":"r1","to":"r2","targetPort":5001,"wssPort":40001,"listening":true,"kind":"DNS"}],
             "links":[],
             "pairs":[%s],
             "lines":[{"first":"r1","second":"r2","state":"UP","strength":-61.5,"rate":0}]}
            """.formatted(pair("UP"));

    private static String pair(String state) {
        return """
                {"first":"r1","second":"r2","state":"%s","forced":false,"strength":-61.5,"distance":null,
                 "bytesFirstToSecond":1000,"bytesSecondToFirst":20,"rateFirstToSecond":100.0,"rateSecondToFirst":2.0,
                 "connections":1,"breaks":0,"resumes":0,"upShare":1.0,"lastClose":null,
                 "linkRateFirstToSecond":0,"linkRateSecondToFirst":0,
                 "udpFirstToSecond":{"datagrams":3,"bytes":30,"droppedBroken":0,"droppedQueue":1,"lost":0}}
                """.formatted(state);
    }

    private static JsonNode json(String text) throws Exception {
        return JsonNode.parse(text, JsonLimits.DEFAULT);
    }

    @Test
    void theSnapshotIsTheTablesAndTheMapInTheHubsOrder() throws Exception {
        ServerState state = new ServerState();
        state.replace(json(STATE));
        ServerView view = state.view();
        assertEquals(List.of("r1", "r2"), view.hub().robots().stream().map(r -> r.name()).toList());
        assertTrue(Double.isNaN(view.hub().robots().get(0).airtime()), "null is NaN");
        assertEquals(40001, view.hub().ports().get(0).wssPort());
        assertEquals(PairState.UP, view.hub().pairs().get(0).state());
        assertTrue(Double.isNaN(view.hub().pairs().get(0).distance()));
        assertEquals(1, view.hub().pairs().get(0).udpFirstToSecond().droppedQueue());
        assertEquals(new Position(1, 2, 0), view.robots().get(0).position());
        assertNull(view.robots().get(1).position());
        assertEquals(30.0, view.cutoff());
        assertEquals(1, view.walls().size());
        assertEquals("DistanceOnly", view.model());
        assertEquals(50000, view.controlPort());
        assertFalse(view.operator());
    }

    @Test
    void anEventReplacesEntriesByTheirKeyAndRemovedTakesThemAway() throws Exception {
        ServerState state = new ServerState();
        state.replace(json(STATE));
        assertTrue(state.apply("pairs", json("[" + pair("FORCED_DOWN") + "]")));
        assertEquals(PairState.FORCED_DOWN, state.view().hub().pairs().get(0).state());
        assertEquals(1, state.view().hub().pairs().size());
        state.apply("removed", json("{\"robots\":[\"r2\"],\"ports\":[{\"from\":\"r1\",\"to\":\"r2\",\"targetPort\":5001,\"wssPort\":40001}],"
                + "\"lines\":[{\"first\":\"r1\",\"second\":\"r2\"}]}"));
        ServerView view = state.view();
        assertEquals(List.of("r1"), view.hub().robots().stream().map(r -> r.name()).toList());
        assertEquals(List.of(), view.hub().ports());
        assertEquals(List.of(), view.lines());
        assertFalse(state.apply("somethingNew", json("{}")), "an unknown type is ignored");
    }

    @Test
    void theReplayComesAndGoes() throws Exception {
        ServerState state = new ServerState();
        state.replace(json(STATE));
        assertNull(state.replay());
        state.apply("replay", json("{\"timeSeconds\":12.5,\"durationSeconds\":300,\"speed\":2,\"playing\":true,\"pollSeconds\":12.4}"));
        RemoteReplay replay = new RemoteReplay((path, body) -> { });
        replay.follow(state.replay());
        assertTrue(replay.running());
        assertEquals(12.5, replay.timeSeconds());
        assertEquals(2, replay.speed());
        state.apply("replay", json("null"));
        replay.follow(state.replay());
        assertFalse(replay.running());
    }

    /** r1 reaches r2 (one hop, the base r2); r2 has no route back: the monitor lists only the routes that exist. */
    private static final String ROUTES = """
            {"base":"r2","rule":"FASTEST_SHARED_AIRTIME","shaped":true,"cutOff":[],
             "routes":[{"from":"r1","to":"r2","hops":1,"path":["r1","r2"],
                        "legs":[[-61.5,2000000]],"weakest":0,"rateBound":2000000}]}
            """;

    @Test
    void theRoutesAreATableOfTheServersRoutesAndEveryOrderedPairsRow() throws Exception {
        ServerState state = new ServerState();
        state.replace(json(STATE.replace("\"lines\":[", "\"routes\":" + ROUTES + ",\"lines\":[")));
        ServerView view = state.view();
        assertEquals(List.of("r1", "r2"), view.routes().route("r1", "r2").path());
        assertEquals(2_000_000, view.routes().route("r1", "r2").rateBound());
        assertEquals(-61.5, view.routes().route("r1", "r2").legs().get(0).strength());
        assertTrue(view.routes().rule().shaped());
        assertEquals("r2", view.routes().base());
        assertFalse(view.routes().isCutOff("r1"));
        assertFalse(view.routes().route("r2", "r1").exists());
        assertEquals(List.of("r1 r2 1", "r2 r1 -1"), view.allRoutes().stream().map(r -> r.from() + " " + r.to() + " " + r.hops()).toList());

        assertTrue(state.apply("routes", json("{\"base\":\"r2\",\"rule\":\"STRONGEST\",\"shaped\":false,\"cutOff\":[\"r1\"],\"routes\":[]}")));
        view = state.view();
        assertTrue(view.routes().isCutOff("r1"));
        assertFalse(view.routes().route("r1", "r2").exists());
        assertEquals(2, view.allRoutes().size());
        state.apply("removed", json("{\"robots\":[\"r2\"]}"));
        assertEquals(List.of(), state.view().allRoutes(), "no row for a robot gone");
    }

    @Test
    void routeChangesReplaceTheRoutesTheyNameAndTakeAwayThoseGone() throws Exception {
        ServerState state = new ServerState();
        assertThrows(JsonException.class, () -> state.apply("routeChanges", json("{\"cutOff\":[],\"routes\":[],\"gone\":[]}")),
                "changes before any routes");
        state.replace(json(STATE.replace("\"lines\":[", "\"routes\":" + ROUTES + ",\"lines\":[")));
        assertTrue(state.apply("routeChanges", json("""
                {"cutOff":[],"routes":[{"from":"r2","to":"r1","hops":1,"path":["r2","r1"],
                   "legs":[[-70,1000000]],"weakest":0,"rateBound":1000000}],
                 "gone":[]}""")));
        ServerView view = state.view();
        assertEquals(1_000_000, view.routes().route("r2", "r1").rateBound(), "the route told");
        assertEquals(2_000_000, view.routes().route("r1", "r2").rateBound(), "the route not named, as it was");
        assertEquals("r2", view.routes().base());
        state.apply("routeChanges", json("{\"cutOff\":[\"r1\"],\"routes\":[],\"gone\":[{\"from\":\"r1\",\"to\":\"r2\"}]}"));
        view = state.view();
        assertFalse(view.routes().route("r1", "r2").exists());
        assertTrue(view.routes().isCutOff("r1"), "no route to the base: cut off");
        assertTrue(view.routes().route("r2", "r1").exists());
        state.replace(json(STATE.replace("\"lines\":[", "\"routes\":" + ROUTES + ",\"lines\":[")));
        assertTrue(state.view().routes().route("r1", "r2").exists(), "a snapshot replaces what the changes left");
        assertFalse(state.view().routes().route("r2", "r1").exists());
    }

    @Test
    void aStateWithoutRoutesHasNone() throws Exception {
        ServerState state = new ServerState();
        state.replace(json(STATE));
        assertEquals(0, state.view().routes().robots().size());
        assertEquals(List.of(), state.view().allRoutes());
    }
}
