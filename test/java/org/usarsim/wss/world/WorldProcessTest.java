package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.hub.Sockets.readLine;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.http.WebSocket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.app.ServerProcess;
import org.usarsim.wss.ros.MessageType;
import org.usarsim.wss.ros.PoseDecoder;
import org.usarsim.wss.ros.RobotPose;

/** {@code Main --world FILE --bind 127.0.0.1 --port 0} as a user runs it, in a child process; its mistakes: WorldCommandLineTest. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class WorldProcessTest {

    private static final String CORRIDOR = "docs/examples/corridor.world";
    private static final Pattern LISTENING = Pattern.compile(
            "^\\d{4}-\\d\\d-\\d\\d \\d\\d:\\d\\d:\\d\\d\\.\\d{3} INFO world server listening on 127\\.0\\.0\\.1:(\\d+)"
            + " with 2 robots and 4 walls from " + Pattern.quote(CORRIDOR) + "$");

    private static final Pattern ROSBRIDGE = Pattern.compile(
            "^\\d{4}-\\d\\d-\\d\\d \\d\\d:\\d\\d:\\d\\d\\.\\d{3} INFO rosbridge v2 on ws://127\\.0\\.0\\.1:(\\d+): .*$");

    private final List<ServerProcess> servers = new ArrayList<>();
    private final List<AutoCloseable> closeables = new ArrayList<>();

    @AfterEach
    void destroyEverything() throws Exception {
        for (AutoCloseable closeable : closeables) {
            closeable.close();
        }
        for (ServerProcess server : servers) {
            server.kill();
        }
    }

    @Test
    void servesTheWorldFileAndStopsOnSigterm() throws Exception {
        ServerProcess server = start("--world", CORRIDOR, "--bind", "127.0.0.1", "--port", "0");
        int port = awaitPort(server);
        assertTrue(port > 0, "the OS chose a port: " + port);

        Socket client = connect(port);
        String peer = "client 127.0.0.1:" + client.getLocalPort();
        client.getOutputStream().write("GETPOS\r\nGETOBS {From Base} {To Scout}\r\n".getBytes(StandardCharsets.US_ASCII));
        String positions = readLine(client);
        assertTrue(positions.matches("POSITIONS \\{Robots 2\\} \\{Name Base Location 0\\.0000,0\\.0000,0\\.4500 BatteryEmpty False\\}"
                + " \\{Name Scout Location \\d+\\.\\d{4},0\\.0000,0\\.4500 BatteryEmpty False\\}\r\n"), positions);
        assertEquals("NUMOBS {From Base} {To Scout} {ObstCount 0.0000}\r\n", readLine(client));
        server.awaitLine(line -> line.endsWith(" INFO " + peer + " connected"));
        client.close();
        server.awaitLine(line -> line.endsWith(" INFO " + peer + " left"));

        Socket stillConnected = connect(port);
        server.sigterm();
        assertEquals(0, server.awaitExit(), "exit code after SIGTERM; stderr: " + server.stderr());
        assertEquals(-1, stillConnected.getInputStream().read(), "clients are closed");
        assertThrows(ConnectException.class, () -> connect(port), "no longer listening");
        assertTrue(server.stdoutSoFar().stream().anyMatch(line -> line.endsWith(" INFO world server stopped")),
                server.stdoutSoFar().toString());
        assertEquals("", server.stderr());
    }

    @Test
    void sigtermRightAfterTheListeningLineExitsZero() throws Exception {
        for (int attempt = 1; attempt <= 3; attempt++) {
            ServerProcess server = start("--world", CORRIDOR, "--bind", "127.0.0.1", "--port", "0");
            awaitPort(server);
            server.sigterm();
            assertEquals(0, server.awaitExit(), "attempt " + attempt + "; stdout: " + server.stdoutSoFar());
        }
    }

    @Test
    void aPortInUseExitsOneNamingAddressAndPort() throws Exception {
        ServerSocket taken = new ServerSocket(0, 50, InetAddress.getByName("127.0.0.1"));
        closeables.add(taken);
        ServerProcess server = start("--world", CORRIDOR, "--bind", "127.0.0.1", "--port", String.valueOf(taken.getLocalPort()));
        assertEquals(1, server.awaitExit(), "stdout: " + server.stdoutSoFar() + "; stderr: " + server.stderr());
        String error = server.stderr().strip();
        assertFalse(error.contains("\n"), "one line: " + error);
        assertTrue(error.startsWith("wss: cannot listen on 127.0.0.1:" + taken.getLocalPort() + ": "), error);
        assertTrue(error.toLowerCase().contains("in use"), "says why: " + error);
    }

    @Test
    void rosbridgeServesTheSameWorldAndStopsBeforeIt() throws Exception {
        ServerProcess server = start("--world", CORRIDOR, "--bind", "127.0.0.1", "--port", "0", "--rosbridge", "0", "--ros-rate", "50");
        awaitPort(server);
        Matcher line = ROSBRIDGE.matcher(server.awaitLine(text -> ROSBRIDGE.matcher(text).matches()));
        assertTrue(line.matches());
        assertTrue(line.group().endsWith(", at 50 Hz"), line.group());
        ReceivedFrames received = new ReceivedFrames();
        WebSocket socket = received.connect(Integer.parseInt(line.group(1)));
        closeables.add(socket::abort);
        socket.sendText("{\"op\":\"subscribe\",\"topic\":\"/gazebo/model_states\",\"throttle_rate\":200}", true).join();
        String frame = received.next();
        List<RobotPose> poses = new PoseDecoder(MessageType.MODEL_STATES).decode(frame);
        assertEquals(List.of("Base", "Scout"), poses.stream().map(RobotPose::name).toList());
        assertEquals(new RobotPose("Base", 0, 0, 0.45, RobotPose.NO_STAMP), poses.get(0));
        server.sigterm();
        assertEquals(0, server.awaitExit(), "exit code after SIGTERM; stderr: " + server.stderr());
        List<String> log = server.stdoutSoFar();
        int rosbridgeStopped = indexOf(log, " INFO rosbridge stopped");
        assertTrue(rosbridgeStopped >= 0 && rosbridgeStopped < indexOf(log, " INFO world server stopped"), log.toString());
    }

    private static int indexOf(List<String> lines, String end) {
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).endsWith(end)) {
                return i;
            }
        }
        return -1;
    }

    // ---- helpers ----

    private ServerProcess start(String... args) throws Exception {
        ServerProcess server = ServerProcess.start(args);
        servers.add(server);
        return server;
    }

    private static int awaitPort(ServerProcess server) throws InterruptedException {
        Matcher matcher = LISTENING.matcher(server.awaitLine(line -> LISTENING.matcher(line).matches()));
        assertTrue(matcher.matches());
        return Integer.parseInt(matcher.group(1));
    }

    private Socket connect(int port) throws IOException {
        Socket socket = new Socket();
        closeables.add(socket);
        socket.connect(new InetSocketAddress(InetAddress.getByName("127.0.0.1"), port), (int) ServerProcess.WAIT.toMillis());
        socket.setSoTimeout((int) ServerProcess.WAIT.toMillis());
        return socket;
    }
}
