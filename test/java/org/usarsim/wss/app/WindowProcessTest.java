package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.gui.Gui;
import org.usarsim.wss.hub.TestRobot;

/**
 * {@code java -jar wss.jar} without {@code --headless}, as a process: the window with
 * {@code --config} and {@code --start} (on the tests' display), SIGTERM while it is open, and no
 * display at all. The command line's mistakes and --help: CommandLineTest.
 */
@Timeout(60)
@Tag("slow")
class WindowProcessTest {

    @TempDir
    Path dir;

    private ServerProcess server;

    @AfterEach
    void kill() throws Exception {
        if (server != null) {
            server.kill();
        }
    }

    private Path config() throws Exception {
        return Files.write(dir.resolve("wss.properties"), List.of("wss.bindAddress = 127.0.0.1", "wss.port = 0"));
    }

    @Test
    void theWindowStartsAtOnceWithStartAndSigtermStopsItWithExitZero() throws Exception {
        Gui.requireDisplay();
        server = ServerProcess.start(dir.resolve("prefs"), Map.of(), "--config", config().toString(), "--start");
        int port = Integer.parseInt(server.awaitListening().group(1));
        try (Socket robot = new Socket("127.0.0.1", port)) {
            robot.setSoTimeout(10_000);
            robot.getOutputStream().write("INIT {Robot R1}\r\n".getBytes(StandardCharsets.UTF_8));
            InputStream in = robot.getInputStream();
            assertEquals("INITREPLY {Status OK}\r\n", new String(in.readNBytes(23), StandardCharsets.UTF_8));
            server.sigterm();
            assertEquals(0, server.awaitExit());
            assertEquals(-1, in.read(), "the robot's control connection was closed");
        }
        assertTrue(server.stdoutSoFar().stream().noneMatch(line -> line.contains("running headless")), server.stdoutSoFar().toString());
    }

    /**
     * Issue 36, item 13: SIGTERM with two robots connected, a connection each way. The robots are
     * deregistered, and the connections terminated, before "WSS stopped", the last line; every line
     * is in the server's one format (none in java.util.logging's own two-line format after it).
     */
    @Test
    void sigtermWithRobotsConnectedDeregistersThemBeforeTheLastLineAllInOneFormat() throws Exception {
        Gui.requireDisplay();
        server = ServerProcess.start(dir.resolve("prefs"), Map.of(), "--config", config().toString(), "--start");
        int port = Integer.parseInt(server.awaitListening().group(1));
        try (TestRobot scout = new TestRobot(port, "127.0.0.1"); TestRobot base = new TestRobot(port, "127.0.0.1")) {
            ServerSocket scoutAccepts = scout.initAccepting("Scout");
            ServerSocket baseAccepts = base.initAccepting("Base");
            try (Socket toBase = scout.connect(scout.dns("Base", 0)); Socket atBase = baseAccepts.accept();
                    Socket toScout = base.connect(base.dns("Scout", 0)); Socket atScout = scoutAccepts.accept()) {
                toBase.getOutputStream().write('x');
                assertEquals('x', atBase.getInputStream().read());
                server.awaitLine(line -> line.endsWith("connection established Base -> Scout:" + scoutAccepts.getLocalPort()));
                server.sigterm();
                assertEquals(0, server.awaitExit());
            }
        }
        List<String> lines = server.stdoutSoFar();
        String oneFormat = "\\d{4}-\\d{2}-\\d{2} \\d{2}:\\d{2}:\\d{2}\\.\\d{3} (INFO|WARNING|SEVERE|FINE) .*";
        assertTrue(lines.stream().allMatch(line -> line.matches(oneFormat)), lines.toString());
        assertEquals("", server.stderr(), "nothing in another format on standard error");
        assertTrue(lines.get(lines.size() - 1).endsWith(" INFO WSS stopped"), "the last line: " + lines);
        int stopped = lines.size() - 1;
        for (String robot : List.of("Base", "Scout")) {
            int deregistered = indexOf(lines, " INFO deregistered " + robot);
            assertTrue(deregistered >= 0 && deregistered < stopped, robot + " deregistered before WSS stopped: " + lines);
        }
        assertEquals(2, lines.stream().filter(line -> line.contains(" INFO connection terminated ")).count(), lines.toString());
    }

    private static int indexOf(List<String> lines, String ending) {
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).endsWith(ending)) {
                return i;
            }
        }
        return -1;
    }

    @Test
    void withoutADisplayItSaysSoInOneLineAndRunsHeadless() throws Exception {
        Map<String, String> noDisplay = new HashMap<>();
        noDisplay.put("DISPLAY", null);
        server = ServerProcess.start(dir.resolve("prefs"), noDisplay, "--config", config().toString());
        server.awaitListening();
        assertEquals(1, server.stdoutSoFar().stream()
                .filter(line -> line.endsWith("INFO no display (DISPLAY is unset): running headless")).count(),
                server.stdoutSoFar().toString());
        server.sigterm();
        assertEquals(0, server.awaitExit());
    }
}
