package org.usarsim.wss.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.logging.Level;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.ScriptedModel;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.ros.Json;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.shaping.ShapingConfig;

/** The monitor endpoint over real sockets (docs/monitor.md): auth, state, events, metrics, the operator's POSTs, the stream limit. */
class MonitorServerTest {

    static final String VIEWER = "viewer-token-0123456789abcdef";
    static final String OPERATOR = "operator-token-0123456789abcdef";

    @TempDir
    Path dir;
    private TestHub server;
    private MonitorServer monitor;
    private final HttpClient client = HttpClient.newHttpClient();

    @BeforeEach
    void start() throws Exception {
        server = new TestHub(new ScriptedModel(), true, 65536);
        Path tokens = tokenFile(dir, "viewer " + VIEWER + "\n# a comment\noperator " + OPERATOR + "\n");
        monitor = MonitorServer.open(new MonitorConfig(-1, InetAddress.getLoopbackAddress(), tokens, 3, null, null),
                new Watched(server.hub, new ScriptedModel(), Map.of("scripted.key", "1"), ShapingConfig.OFF, "127.0.0.1"));
        monitor.start();
    }

    @AfterEach
    void stop() {
        monitor.close();
        server.close();
    }

    static Path tokenFile(Path dir, String text) throws Exception {
        Path file = dir.resolve("tokens");
        Files.writeString(file, text);
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-------"));
        return file;
    }

    private HttpResponse<String> get(String path, String token) throws Exception {
        HttpRequest.Builder request = HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + monitor.port() + path));
        if (token != null) {
            request.header("Authorization", "Bearer " + token);
        }
        return client.send(request.build(), HttpResponse.BodyHandlers.ofString());
    }

    private HttpResponse<String> post(String path, String token, String body) throws Exception {
        return client.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + monitor.port() + path))
                .header("Authorization", "Bearer " + token).POST(HttpRequest.BodyPublishers.ofString(body)).build(),
                HttpResponse.BodyHandlers.ofString());
    }

    static Map<String, Object> json(String text) throws Exception {
        return SseClient.map(Json.parse(text, JsonLimits.DEFAULT));
    }

    @Test
    void aRequestWithoutAValidTokenIs401WithOneLineNamingTheAddressAndTheTokenIsNeverLogged() throws Exception {
        try (LogCapture log = LogCapture.of("", Level.ALL)) {
            HttpResponse<String> none = get("/api/state", null);
            assertEquals(401, none.statusCode());
            assertEquals("Bearer realm=\"wss\"", none.headers().firstValue("WWW-Authenticate").orElse(null));
            assertEquals(Map.of("error", "unauthorized"), json(none.body()));
            assertEquals(401, get("/metrics", "wrong-token-0123456789abcdef").statusCode());
            assertEquals(401, get("/nowhere", VIEWER + "x").statusCode(), "the token before the path");
            assertEquals(200, get("/api/state", VIEWER).statusCode());
            assertEquals(404, get("/nowhere", VIEWER).statusCode());
            HttpResponse<String> wrongMethod = post("/api/state", OPERATOR, "");
            assertEquals(405, wrongMethod.statusCode());
            assertEquals("GET", wrongMethod.headers().firstValue("Allow").orElse(null));
            HttpResponse<String> viewerForce = post("/api/force", VIEWER, "{Robot A} {Peer B} {State Down}");
            assertEquals(403, viewerForce.statusCode());
            assertEquals(Map.of("error", "operator token needed"), json(viewerForce.body()));
            assertEquals(3, log.count(Level.WARNING, "monitor: refused a request from 127.0.0.1 (401"), log.toString());
            for (String message : log.messages(Level.ALL)) {
                assertFalse(message.contains("token-0123456789abcdef"), message);
            }
        }
    }

    @Test
    void theStateShowsTheRobotsTheirPortsAndAForcedPairAndThePostAnswersAsTheControlPort() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); LogCapture log = LogCapture.of("", Level.INFO)) {
            r1.init("R1", 5001);
            r2.init("R2", 5002);
            int wssPort = r1.dns("R2", 5002);
            HttpResponse<String> forced = post("/api/force", OPERATOR, "{Robot R1} {Peer R2} {State Down}");
            assertEquals(200, forced.statusCode(), forced.body());
            assertEquals(Map.of("reply", "FORCEREPLY {Status OK}"), json(forced.body()));
            assertEquals(1, log.count(Level.INFO, "(monitor): FORCE R1 - R2 Down"), log.toString());
            HttpResponse<String> bad = post("/api/force", OPERATOR, "{Robot R1} {Peer R2} {State Sideways}");
            assertEquals(400, bad.statusCode());
            assertEquals(Map.of("error", "State.Must.Be.Down.Up.Or.Model", "reply", "ERROR {Reason State.Must.Be.Down.Up.Or.Model}"),
                    json(bad.body()));
            HttpResponse<String> replay = post("/api/replay", OPERATOR, "");
            assertEquals(400, replay.statusCode());
            assertEquals("Not.A.Replay", json(replay.body()).get("error"));

            Map<String, Object> state = json(get("/api/state", OPERATOR).body());
            assertEquals(true, state.get("operator"));
            assertEquals(false, json(get("/api/state", VIEWER).body()).get("operator"));
            List<?> robots = (List<?>) state.get("robots");
            assertEquals(List.of("R1", "R2"), robots.stream().map(r -> SseClient.map(r).get("name")).toList());
            assertEquals(List.of(5001.0), SseClient.map(robots.get(0)).get("ports").toString().equals("[5001]") ? List.of(5001.0)
                    : SseClient.map(robots.get(0)).get("ports"));
            Map<String, Object> port = SseClient.map(((List<?>) state.get("ports")).get(0));
            assertEquals("R1", port.get("from"));
            assertEquals("R2", port.get("to"));
            assertEquals((double) wssPort, ((Number) port.get("wssPort")).doubleValue());
            assertEquals(false, port.get("listening"), "forced down: the port does not listen");
            Map<String, Object> pair = SseClient.map(((List<?>) state.get("pairs")).get(0));
            assertEquals("FORCED_DOWN", pair.get("state"));
            assertEquals(true, pair.get("forced"));
            Map<String, Object> line = SseClient.map(((List<?>) state.get("lines")).get(0));
            assertEquals("FORCED_DOWN", line.get("state"));
            assertEquals(Map.of("scripted.key", "1"), SseClient.map(state.get("model")).get("settings"));
            assertEquals(null, state.get("replay"));
        }
    }

    @Test
    void aStreamStartsWithASnapshotAndThenTellsAPairChange() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); SseClient events = SseClient.open(client, monitor.port(), VIEWER, null)) {
            assertEquals(200, events.status);
            SseClient.Event snapshot = events.next();
            assertEquals("snapshot", snapshot.type());
            assertEquals(SseClient.map(snapshot.json()).get("lastEventId"), snapshot.id());
            r1.init("R1", 5001);
            r2.init("R2", 5002);
            r1.dns("R2", 5002);
            events.await("pairs", pairs -> ((List<?>) pairs).stream().anyMatch(p -> SseClient.map(p).get("state").equals("UP")));
            post("/api/force", OPERATOR, "{Robot R1} {Peer R2} {State Down}");
            events.await("pairs", pairs -> ((List<?>) pairs).stream().anyMatch(p -> SseClient.map(p).get("state").equals("FORCED_DOWN")));
        }
    }

    @Test
    void aStreamThatReconnectsWithLastEventIdGetsWhatItMissedAndOnePastTheHistoryASnapshot() throws Exception {
        String last;
        try (TestRobot r1 = server.robot(); SseClient events = SseClient.open(client, monitor.port(), VIEWER, null)) {
            assertEquals("snapshot", events.next().type());
            r1.init("R1", 5001);
            last = events.await("robots", robots -> true).id();
        }
        try (TestRobot r2 = server.robot(); SseClient other = SseClient.open(client, monitor.port(), OPERATOR, null)) {
            other.next(); // a stream keeps the history recorded
            r2.init("R2", 5002);
            other.await("robots", robots -> ((List<?>) robots).stream().anyMatch(r -> SseClient.map(r).get("name").equals("R2")));
            try (SseClient resumed = SseClient.open(client, monitor.port(), VIEWER, last)) {
                assertEquals(200, resumed.status);
                SseClient.Event first = resumed.next();
                assertNotEquals("snapshot", first.type(), first.data());
                String run = last.substring(0, last.indexOf('-'));
                assertEquals(run + "-" + (Long.parseLong(last.substring(run.length() + 1)) + 1), first.id());
            }
            try (SseClient stranger = SseClient.open(client, monitor.port(), VIEWER, "00000000-5")) {
                assertEquals("snapshot", stranger.next().type(), "another run's id");
            }
        }
    }

    @Test
    void metricsAreInThePrometheusTextFormat() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            r1.init("R1", 5001);
            r2.init("R2", 5002);
            r1.dns("R2", 5002);
            HttpResponse<String> metrics = get("/metrics", VIEWER);
            assertEquals(200, metrics.statusCode());
            assertEquals("text/plain; version=0.0.4; charset=utf-8", metrics.headers().firstValue("Content-Type").orElse(null));
            Pattern sample = Pattern.compile("([a-zA-Z_:][a-zA-Z0-9_:]*)(\\{([a-zA-Z_][a-zA-Z0-9_]*=\"([^\"\\\\]|\\\\.)*\",?)*\\})? (-?[0-9.eE+-]+|NaN|[+-]Inf)");
            String typed = null;
            for (String line : metrics.body().split("\n")) {
                if (line.startsWith("# TYPE ")) {
                    typed = line.split(" ")[2];
                    assertTrue(line.endsWith(" gauge") || line.endsWith(" counter"), line);
                } else if (!line.startsWith("# HELP wss_")) {
                    var matcher = sample.matcher(line);
                    assertTrue(matcher.matches(), line);
                    assertEquals(typed, matcher.group(1), "a sample under its own TYPE: " + line);
                }
            }
            assertTrue(metrics.body().contains("\nwss_robots 2\n"), metrics.body());
            assertTrue(metrics.body().contains("wss_pair_bytes_total{robot=\"R1\",peer=\"R2\"} 0\n"), metrics.body());
        }
    }

    @Test
    void pastMaxClientsStreamsTheNextIs503() throws Exception {
        try (SseClient one = SseClient.open(client, monitor.port(), VIEWER, null);
                SseClient two = SseClient.open(client, monitor.port(), VIEWER, null);
                SseClient three = SseClient.open(client, monitor.port(), OPERATOR, null)) {
            one.next();
            two.next();
            three.next();
            HttpResponse<String> third = get("/api/events", VIEWER);
            assertEquals(503, third.statusCode());
            assertEquals(Map.of("error", "too many streams"), json(third.body()));
        }
    }
}
