package org.usarsim.wss.sim;

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
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.usarsim.wss.app.ServerProcess;

/** {@code Main --world FILE --bind 127.0.0.1 --port 0} as a user runs it, in a child process. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class WorldProcessTest {

    private static final String CORRIDOR = "docs/examples/corridor.world";
    private static final Pattern LISTENING = Pattern.compile(
            "^\\d{4}-\\d\\d-\\d\\d \\d\\d:\\d\\d:\\d\\d\\.\\d{3} INFO world server listening on 127\\.0\\.0\\.1:(\\d+)"
            + " with 2 robots and 4 walls from " + Pattern.quote(CORRIDOR) + "$");

    @TempDir
    Path dir;

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
    void aBadWorldFileExitsTwoBeforeBinding() throws Exception {
        Path world = dir.resolve("bad.world");
        Files.writeString(world, "# a mistake on line 3\nrobot A 0,0,0\npath A speed 0 loop 5,5\n", StandardCharsets.UTF_8);
        ServerProcess server = start("--world", world.toString(), "--bind", "127.0.0.1", "--port", "0");
        assertEquals(2, server.awaitExit(), "stderr: " + server.stderr());
        assertEquals("wss: " + world + ":3: the speed must be above 0 metres per second: 0 (path A speed 0 loop 5,5)\n",
                server.stderr().replace("\r\n", "\n"));
        assertTrue(server.stdoutSoFar().stream().noneMatch(line -> line.contains("listening")), server.stdoutSoFar().toString());
    }

    @Test
    void aMissingWorldFileExitsTwo() throws Exception {
        Path absent = dir.resolve("absent.world");
        ServerProcess server = start("--world", absent.toString(), "--bind", "127.0.0.1", "--port", "0");
        assertEquals(2, server.awaitExit());
        assertEquals("wss: " + absent + ": no such file", server.stderr().strip());
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

    @ParameterizedTest(name = "[{index}] {0}")
    @CsvSource(delimiter = '|', value = {
        "--port 7435                                      | --port and --bind are for the world server",
        "--bind 127.0.0.1                                 | --port and --bind are for the world server",
        "--headless --port 0                              | --port and --bind are for the world server",
        "--world " + CORRIDOR + " --headless              | without --headless or --config",
        "--world " + CORRIDOR + " --port 65536            | --port 65536 is not a port number from 0 to 65535",
        "--world " + CORRIDOR + " --port seven            | --port seven is not a port number",
        "--world " + CORRIDOR + " --bind no.such.host.invalid | --bind no.such.host.invalid is not an address",
        "--world                                          | --world needs a value",
        "--world " + CORRIDOR + " --port                  | --port needs a value",
    })
    void commandLineMistakesExitTwo(String args, String message) throws Exception {
        ServerProcess server = start(args.strip().split(" +"));
        assertEquals(2, server.awaitExit(), "stderr: " + server.stderr());
        assertTrue(server.stderr().startsWith("wss: "), server.stderr());
        assertTrue(server.stderr().contains(message), server.stderr());
        assertTrue(server.stdoutSoFar().isEmpty(), server.stdoutSoFar().toString());
    }

    @Test
    void helpDescribesTheWorldServer() throws Exception {
        ServerProcess server = start("--help");
        assertEquals(0, server.awaitExit());
        String help = String.join("\n", server.stdoutSoFar());
        assertTrue(help.contains("--world FILE [--port N] [--bind ADDRESS]"), help);
        assertTrue(help.contains("default 7435"), help);
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
