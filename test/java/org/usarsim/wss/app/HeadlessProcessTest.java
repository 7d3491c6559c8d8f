package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.hub.Sockets.readLine;
import static org.usarsim.wss.hub.Sockets.send;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Runs the real server as a child process, as a user does:
 * {@code java -cp <classes> org.usarsim.wss.app.Main --headless --config FILE}. Every config
 * binds 127.0.0.1 and lets the OS choose the control port, read back from the log. A bad
 * command line or config ends before anything runs: CommandLineTest, in the test JVM.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class HeadlessProcessTest {

    private static final Pattern TIMESTAMPED = Pattern.compile(
            "^(\\d{4}-\\d{2}-\\d{2} \\d{2}:\\d{2}:\\d{2}\\.\\d{3}) (SEVERE|WARNING|INFO|CONFIG|FINE|FINER|FINEST) \\S.*");
    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss.SSS");

    @TempDir
    Path dir;

    private final List<ServerProcess> servers = new ArrayList<>();
    private final List<AutoCloseable> closeables = new ArrayList<>();

    @AfterEach
    void destroyEverything() throws Exception {
        for (AutoCloseable closeable : closeables) {
            try {
                closeable.close();
            } catch (IOException e) {
                // best effort
            }
        }
        for (ServerProcess server : servers) {
            server.kill();
        }
    }

    // ---- the cases ----

    @Test
    void startsAnswersInitAndLogsWithTimestamps() throws Exception {
        ServerProcess server = start("--headless", "--config", config(Map.of()).toString());
        Matcher listening = server.awaitListening();
        assertEquals("NoopPropagationModel", listening.group(2));
        int port = Integer.parseInt(listening.group(1));
        assertTrue(port > 0, "the OS chose a port: " + port);

        Socket robot = connect(port);
        send(robot, "INIT {Robot R1} {Port 5000}\r\n");
        assertEquals("INITREPLY {Status OK}\r\n", readLine(robot));

        server.awaitLine(line -> line.contains("registered R1"));
        List<String> lines = server.stdoutSoFar();
        assertFalse(lines.isEmpty());
        LocalDateTime now = LocalDateTime.now();
        for (String line : lines) {
            Matcher matcher = TIMESTAMPED.matcher(line);
            assertTrue(matcher.matches(), "a log line without a timestamp: '" + line + "'");
            LocalDateTime time = LocalDateTime.parse(matcher.group(1), TIME);
            assertTrue(Math.abs(Duration.between(time, now).toSeconds()) < 120,
                    "the timestamp is the time of the event: " + line + " (now " + now + ")");
        }
        assertTrue(server.process.isAlive(), "still running");
        assertEquals("", server.stderr(), "nothing on standard error");
    }

    @Test
    void withTheEventLogOnEveryEventIsACsvLineInANewFile() throws Exception {
        Path logs = dir.resolve("event logs");
        ServerProcess server = start("--headless", "--config",
                config(Map.of("wss.eventLog", "true", "wss.eventLogDir", logs.toString())).toString());
        int port = Integer.parseInt(server.awaitListening().group(1));
        try (Socket r1 = connect(port); Socket r2 = connect(port)) {
            send(r1, "INIT {Robot R1} {Port 5000,5001}\r\n");
            assertEquals("INITREPLY {Status OK}\r\n", readLine(r1));
            send(r2, "INIT {Robot R2} {Port 6000}\r\n");
            assertEquals("INITREPLY {Status OK}\r\n", readLine(r2));
        }
        for (int robot = 0; robot < 2; robot++) {
            server.awaitLine(line -> line.contains("deregistered R"));
        }
        server.sigterm();
        assertEquals(0, server.awaitExit(), "stderr: " + server.stderr());
        List<Path> files;
        try (var listing = Files.list(logs)) {
            files = listing.toList();
        }
        assertEquals(1, files.size(), "one file per run: " + files);
        assertTrue(files.get(0).getFileName().toString().matches("log-\\d{4}\\.\\d\\d\\.\\d\\d-\\d\\d\\.\\d\\d\\.\\d\\d\\.\\d{3}\\.txt"),
                files.get(0).toString());
        List<String> lines = Files.readAllLines(files.get(0));
        String time = "\\d\\d:\\d\\d:\\d\\d\\.\\d{3}";
        assertEquals(5, lines.size(), String.join("\n", lines));
        assertTrue(lines.get(0).matches("SETTING," + time + ",wss.seed,0"), "the run's seed first: " + lines.get(0));
        assertTrue(lines.get(1).matches("REGISTERED," + time + ",R1,127\\.0\\.0\\.1,5000:5001"), lines.get(1));
        assertTrue(lines.get(2).matches("REGISTERED," + time + ",R2,127\\.0\\.0\\.1,6000"), lines.get(2));
        assertTrue(lines.stream().skip(3).allMatch(line -> line.matches("DEREGISTERED," + time + ",R[12]")), lines.toString());
    }

    @Test
    void sigtermExitsZeroAndStopsListening() throws Exception {
        ServerProcess server = start("--headless", "--config", config(Map.of()).toString());
        int port = Integer.parseInt(server.awaitListening().group(1));
        Socket robot = connect(port);
        send(robot, "INIT {Robot R1} {Port 5000}\r\n");
        assertEquals("INITREPLY {Status OK}\r\n", readLine(robot));

        server.sigterm();
        assertEquals(0, server.awaitExit(), "exit code after SIGTERM; stderr: " + server.stderr());
        assertEquals(-1, robot.getInputStream().read(), "the robot's control connection is closed");
        assertThrows(ConnectException.class, () -> connect(port), "the control port no longer accepts connections");
        assertTrue(server.stdoutSoFar().stream().anyMatch(line -> line.endsWith("WSS stopped")),
                "logs that it stopped: " + server.stdoutSoFar());
    }

    /**
     * A supervisor (or a script) that waits for the "listening" line and then stops the server
     * must see exit code 0 too. Several tries, since it is a matter of timing.
     */
    @Test
    void sigtermRightAfterTheListeningLineExitsZero() throws Exception {
        for (int attempt = 1; attempt <= 5; attempt++) {
            ServerProcess server = start("--headless", "--config", config(Map.of()).toString());
            server.awaitListening();
            server.sigterm();
            int code = server.awaitExit();
            assertEquals(0, code, "attempt " + attempt + ": SIGTERM sent just after the 'WSS listening' line was logged"
                    + " gave exit code " + code + " (143 = the JVM's default SIGTERM handling: the server's own handler"
                    + " was not installed yet); stdout: " + server.stdoutSoFar());
        }
    }

    @Test
    void controlPortInUseExitsOne() throws Exception {
        ServerSocket taken = holdPort();
        int port = taken.getLocalPort();
        ServerProcess server = start("--headless", "--config", config(Map.of("wss.port", String.valueOf(port))).toString());
        assertEquals(1, server.awaitExit(), "exit code; stderr: " + server.stderr() + "; stdout: " + server.stdoutSoFar());
        String error = server.stderr().strip();
        assertFalse(error.contains("\n"), "a one-line error: " + error);
        assertTrue(error.contains("127.0.0.1:" + port), "names the address and port: " + error);
        assertTrue(error.contains("cannot listen"), error);
        assertTrue(error.toLowerCase().contains("in use"), "says why: " + error);
        assertTrue(server.stdoutSoFar().stream().noneMatch(line -> line.contains("listening")), server.stdoutSoFar().toString());
    }

    // ---- helpers ----

    /** A config binding 127.0.0.1 on a port of the OS's choosing, with these overrides. */
    private Path config(Map<String, String> overrides) throws IOException {
        return ServerProcess.config(dir, overrides);
    }

    private ServerSocket holdPort() throws IOException {
        ServerSocket socket = new ServerSocket(0, 50, InetAddress.getByName("127.0.0.1"));
        closeables.add(socket);
        return socket;
    }

    private Socket connect(int port) throws IOException {
        Socket socket = new Socket();
        closeables.add(socket);
        socket.connect(new InetSocketAddress(InetAddress.getByName("127.0.0.1"), port), (int) ServerProcess.WAIT.toMillis());
        socket.setSoTimeout((int) ServerProcess.WAIT.toMillis());
        return socket;
    }

    private ServerProcess start(String... args) throws Exception {
        ServerProcess server = ServerProcess.start(args);
        servers.add(server);
        return server;
    }
}
