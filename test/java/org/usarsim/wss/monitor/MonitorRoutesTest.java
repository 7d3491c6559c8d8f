package org.usarsim.wss.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.ScriptedModel;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The routes in the monitor (docs/monitor.md, "routes"): in GET /api/state for any token, a
 * {@code routes} event when the table changed, and the base's figures in /metrics (the scripted
 * model's strengths: 0 dBm).
 */
class MonitorRoutesTest {

    @TempDir
    Path dir;
    private final ScriptedModel model = new ScriptedModel();
    private TestHub server;
    private MonitorServer monitor;
    private final HttpClient client = HttpClient.newHttpClient();

    @BeforeEach
    void start() throws Exception {
        server = new TestHub(model, true, 65536);
        Path tokens = MonitorServerTest.tokenFile(dir, "viewer " + MonitorServerTest.VIEWER + "\n");
        monitor = MonitorServer.open(new MonitorConfig(-1, InetAddress.getLoopbackAddress(), tokens, 3, null, null),
                new Watched(server.hub, model, Map.of(), ShapingConfig.OFF, "127.0.0.1"));
        monitor.start();
    }

    @AfterEach
    void stop() {
        monitor.close();
        server.close();
    }

    private String get(String path) throws Exception {
        return client.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + monitor.port() + path))
                .header("Authorization", "Bearer " + MonitorServerTest.VIEWER).build(), HttpResponse.BodyHandlers.ofString()).body();
    }

    /** R1 - R2 and R2 - R3 up as asked, R1 - R3 down: R1 reaches R3 through R2. */
    private void decide(boolean r2r3) {
        Map<RobotPair, Boolean> states = new LinkedHashMap<>();
        states.put(RobotPair.of("R1", "R2"), true);
        states.put(RobotPair.of("R2", "R3"), r2r3);
        states.put(RobotPair.of("R1", "R3"), false);
        server.hub.robotLinks().applyLinkStates(states);
    }

    private static Map<String, Object> route(Object routes, String from, String to) {
        for (Object route : (List<?>) SseClient.map(routes).get("routes")) {
            if (SseClient.map(route).get("from").equals(from) && SseClient.map(route).get("to").equals(to)) {
                return SseClient.map(route);
            }
        }
        return null;
    }

    @Test
    void theStateCarriesEveryPairsRouteForAViewersTokenAndMetricsTheBase() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); TestRobot r3 = server.robot()) {
            r1.init("R1", 5001);
            r2.init("R2", 5002);
            r3.init("R3", 5003);
            server.hub.setRouteBase("R3");
            decide(true);
            Wait.until("R1's route to R3 in the state", () -> {
                try {
                    Map<String, Object> route = route(MonitorServerTest.json(get("/api/state")).get("routes"), "R1", "R3");
                    return route != null && route.get("path").equals(List.of("R1", "R2", "R3"));
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            Map<String, Object> routes = SseClient.map(MonitorServerTest.json(get("/api/state")).get("routes"));
            assertEquals("R3", routes.get("base"));
            assertEquals(List.of(), routes.get("cutOff"));
            assertEquals(false, routes.get("shaped"));
            Map<String, Object> route = route(routes, "R1", "R3");
            assertEquals(2.0, ((Number) route.get("hops")).doubleValue());
            assertEquals(2, ((List<?>) route.get("legs")).size());
            assertEquals(0.0, ((Number) route.get("weakest")).doubleValue(), "the first leg, R1 to R2, the weakest");
            assertEquals(0.0, ((Number) ((List<?>) ((List<?>) route.get("legs")).get(0)).get(0)).doubleValue(), "its strength");
            assertEquals(6, ((List<?>) routes.get("routes")).size(), "every ordered pair's route");
            String metrics = get("/metrics");
            assertTrue(metrics.contains("\nwss_robots_cut_off 0\n"), metrics);
            assertTrue(metrics.contains("\nwss_route_hops{robot=\"R1\",peer=\"R3\"} 2\n"), metrics);
        }
    }

    @Test
    void aStreamIsToldTheRoutesWhenAPairChanges() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); TestRobot r3 = server.robot();
                SseClient events = SseClient.open(client, monitor.port(), MonitorServerTest.VIEWER, null)) {
            assertEquals("snapshot", events.next().type());
            r1.init("R1", 5001);
            r2.init("R2", 5002);
            r3.init("R3", 5003);
            server.hub.setRouteBase("R3");
            decide(true);
            events.await("routes", routes -> route(routes, "R1", "R3") != null && route(routes, "R1", "R3").get("hops").equals(2.0));
            decide(false);
            events.await("routes", routes -> route(routes, "R1", "R3") == null
                    && SseClient.map(routes).get("cutOff").equals(List.of("R1", "R2")));
        }
    }
}
