package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.hub.Sockets.assertClosedByPeer;
import static org.usarsim.wss.hub.Sockets.readLine;
import static org.usarsim.wss.hub.Sockets.send;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.OptionalDouble;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.Wait;

/** The world server over real sockets on 127.0.0.1, its clock set by the test. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class WorldServerTest {

    private static final int TIMEOUT_MS = 5000;

    /** Both spec robots at t = 10 (Robot2's battery lasts 5 s); Mover covers 1 m a second from (0,0,0) to (10,0,0). */
    private static final String AT_10 = "POSITIONS {Robots 3}"
            + " {Name Robot1 Location 1.2500,-3.0000,0.4500 BatteryEmpty False}"
            + " {Name Robot2 Location 10.0000,2.5000,0.4500 BatteryEmpty True}"
            + " {Name Mover Location 10.0000,0.0000,0.0000 BatteryEmpty False}\r\n";

    private final World world = new World(List.of(
            new WorldRobot("Robot1", new Point(1.25, -3, 0.45), null, OptionalDouble.empty()),
            new WorldRobot("Robot2", new Point(10, 2.5, 0.45), null, OptionalDouble.of(5)),
            new WorldRobot("Mover", new Point(0, 0, 0), new Route(new Point(0, 0, 0), List.of(new Point(10, 0, 0)), 1, false),
                    OptionalDouble.empty())),
            List.of(new Wall(5, -10, 5, 10), new Wall(7, -10, 7, 10), new Wall(-1, 1, 1, 1)));

    private volatile double seconds = 10;
    private WorldServer server;
    private final List<Socket> sockets = new ArrayList<>();

    @BeforeEach
    void start() throws IOException {
        server = new WorldServer(world, new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), () -> seconds);
    }

    @AfterEach
    void stop() throws IOException {
        for (Socket socket : sockets) {
            socket.close();
        }
        server.close();
    }

    @Test
    void getposReplyIsExact() throws IOException {
        Socket client = connect();
        send(client, "GETPOS\r\n");
        assertEquals(AT_10, readLine(client));
    }

    @Test
    void getobsReplyIsExactAndMinusOneForAnUnknownRobot() throws IOException {
        Socket client = connect();
        send(client, "GETOBS {From Robot1} {To Robot2}\r\n");
        assertEquals("NUMOBS {From Robot1} {To Robot2} {ObstCount 2.0000}\r\n", readLine(client));
        send(client, "GETOBS {From Robot1} {To Ghost}\r\n");
        assertEquals("NUMOBS {From Robot1} {To Ghost} {ObstCount -1.0000}\r\n", readLine(client));
    }

    @Test
    void getwallsListsEveryWallInFileOrderInAnyCase() throws IOException {
        Socket client = connect();
        send(client, "GETWALLS\r\n");
        String walls = "WALLS {Walls 3} {Wall 5.0000,-10.0000,5.0000,10.0000} {Wall 7.0000,-10.0000,7.0000,10.0000}"
                + " {Wall -1.0000,1.0000,1.0000,1.0000}\r\n";
        assertEquals(walls, readLine(client));
        send(client, "getwalls\r\nGETPOS\r\n");
        assertEquals(walls, readLine(client));
        assertEquals(AT_10, readLine(client), "answered in order");
    }

    @Test
    void answersTheWorldAtTheTimeOfTheCommand() throws IOException {
        Socket client = connect();
        seconds = 0;
        send(client, "GETOBS {From Mover} {To Robot1}\r\n");
        assertEquals("NUMOBS {From Mover} {To Robot1} {ObstCount 0.0000}\r\n", readLine(client));
        send(client, "GETPOS\r\n");
        assertTrue(readLine(client).contains("{Name Robot2 Location 10.0000,2.5000,0.4500 BatteryEmpty False}"));
        seconds = 2.5;
        send(client, "GETPOS\r\n");
        assertTrue(readLine(client).contains("{Name Mover Location 2.5000,0.0000,0.0000 BatteryEmpty False}"));
        seconds = 6;
        send(client, "GETOBS {From Mover} {To Robot1}\r\n");
        assertEquals("NUMOBS {From Mover} {To Robot1} {ObstCount 1.0000}\r\n", readLine(client), "the wall at x = 5 is now between");
    }

    @Test
    void anUnknownCommandGetsNoAnswerAndTheNextCommandGetsItsOwn() throws IOException {
        Socket client = connect();
        send(client, "FOO\r\n");
        send(client, "\r\n");
        send(client, "GETPOSITIONS\r\n");
        send(client, "GETOBS {From Robot1}\r\n");
        send(client, "GETPOS\r\n");
        assertEquals(AT_10, readLine(client), "the first answer is the GETPOS's: the lines before it had none");
        send(client, "GETOBS {From Robot1} {To Robot2}\r\n");
        assertEquals("NUMOBS {From Robot1} {To Robot2} {ObstCount 2.0000}\r\n", readLine(client), "and nothing came in between");
    }

    @Test
    void commandsAreMatchedInAnyCaseAsUsarSimDoes() throws IOException {
        Socket client = connect();
        send(client, "getpos\r\nGetObs {From Robot1} {To Robot2}\r\n");
        assertEquals(AT_10, readLine(client));
        assertEquals("NUMOBS {From Robot1} {To Robot2} {ObstCount 2.0000}\r\n", readLine(client));
    }

    @Test
    void pipelinedCommandsInOneWriteAreAnsweredInOrder() throws IOException {
        Socket client = connect();
        send(client, "GETPOS\r\nGETOBS {From Robot2} {To Robot1}\nBAD\r\nGETOBS {From Mover} {To Nobody}\r\nGETPOS\r\n");
        assertEquals(AT_10, readLine(client));
        assertEquals("NUMOBS {From Robot2} {To Robot1} {ObstCount 2.0000}\r\n", readLine(client));
        assertEquals("NUMOBS {From Mover} {To Nobody} {ObstCount -1.0000}\r\n", readLine(client));
        assertEquals(AT_10, readLine(client));
    }

    @Test
    void aLineSplitAcrossWrites() throws IOException {
        Socket client = connect();
        for (String part : List.of("GE", "TOBS {Fro", "m Robot1} {To Rob", "ot2}\r", "\nGETP", "OS", "\n")) {
            send(client, part);
        }
        assertEquals("NUMOBS {From Robot1} {To Robot2} {ObstCount 2.0000}\r\n", readLine(client));
        assertEquals(AT_10, readLine(client), "a bare LF ends a line too");
    }

    @Test
    void twoClientsAtOnce() throws IOException {
        Socket first = connect();
        Socket second = connect();
        send(first, "GETOBS {From Robot1} {To Robot2}\r\n");
        send(second, "GETPOS\r\n");
        assertEquals(AT_10, readLine(second));
        assertEquals("NUMOBS {From Robot1} {To Robot2} {ObstCount 2.0000}\r\n", readLine(first));
        send(second, "GETOBS {From Robot2} {To Mover}\r\n");
        send(first, "GETPOS\r\n");
        assertEquals(AT_10, readLine(first));
        assertEquals("NUMOBS {From Robot2} {To Mover} {ObstCount 0.0000}\r\n", readLine(second));
    }

    @Test
    void aClientLeavingMidLineDoesNotDisturbTheOthers() throws IOException {
        Socket staying = connect();
        send(staying, "GETOBS {From Robot1} ");
        Socket leaving = connect();
        send(leaving, "GETOBS {From Rob");
        leaving.close();
        Socket reset = connect();
        send(reset, "GETP");
        reset.setSoLinger(true, 0);
        reset.close();
        send(staying, "{To Robot2}\r\n");
        assertEquals("NUMOBS {From Robot1} {To Robot2} {ObstCount 2.0000}\r\n", readLine(staying));
        Socket later = connect();
        send(later, "GETPOS\r\n");
        assertEquals(AT_10, readLine(later));
    }

    @Test
    void aLineOverSixtyFourKibibytesDropsThatClientOnly() throws IOException {
        Socket staying = connect();
        Socket flooding = connect();
        byte[] flood = new byte[70 * 1024];
        Arrays.fill(flood, (byte) 'x');
        try {
            flooding.getOutputStream().write(flood);
        } catch (SocketException e) {
            // the server may close before all of it is written
        }
        assertClosedByPeer(flooding, "the flooding client");
        send(staying, "GETPOS\r\n");
        assertEquals(AT_10, readLine(staying));
    }

    @Test
    void aLineOfExactlySixtyFourKibibytesIsOnlyIgnored() throws IOException {
        Socket client = connect();
        send(client, "x".repeat(64 * 1024) + "\r\nGETPOS\r\n");
        assertEquals(AT_10, readLine(client));
    }

    @Test
    void logsClientsComingAndGoingAndLinesWithNoAnswer() throws Exception {
        try (LogCapture log = LogCapture.of("org.usarsim.wss.world", Level.FINE)) {
            List<LogRecord> records = log.records;
            Socket client = connect();
            String peer = "client 127.0.0.1:" + client.getLocalPort();
            send(client, "WHERE {Robot Robot1}\r\nGETPOS\r\n");
            assertEquals(AT_10, readLine(client));
            client.close();
            Wait.until("the server logs that the client left", () -> has(records, Level.INFO, peer + " left"));
            assertTrue(has(records, Level.INFO, peer + " connected"), messages(records));
            assertTrue(has(records, Level.FINE, peer + ": no answer to 'WHERE {Robot Robot1}'"), messages(records));
        }
    }

    @Test
    void fortyQuickClientsWriteFiveLinesEachWayThenOneSummaryEach() throws Exception {
        try (LogCapture log = LogCapture.of("org.usarsim.wss.world", Level.INFO)) {
            List<Socket> clients = new ArrayList<>();
            for (int i = 0; i < 40; i++) {
                Socket client = connect();
                send(client, "GETPOS\r\n");
                assertEquals(AT_10, readLine(client)); // its thread runs: it said "connected", or counted it
                clients.add(client);
            }
            for (Socket client : clients) {
                client.close();
            }
            Wait.until("every client left", () -> server.clientCount() == 0);
            server.close();
            List<String> lines = log.messages(Level.INFO);
            assertEquals(5, lines.stream().filter(line -> line.endsWith(" connected")).count(), lines.toString());
            assertEquals(5, lines.stream().filter(line -> line.endsWith(" left")).count(), lines.toString());
            assertTrue(lines.stream().anyMatch(line -> line.matches("clients connected: 35 more like this from 127\\.0\\.0\\.1 in the last \\d+ s")),
                    lines.toString());
            assertTrue(lines.stream().anyMatch(line -> line.matches("clients left: 35 more like this from 127\\.0\\.0\\.1 in the last \\d+ s")),
                    lines.toString());
        }
    }

    @Test
    void closeStopsListeningAndClosesClients() throws IOException {
        Socket client = connect();
        send(client, "GETPOS\r\n");
        assertEquals(AT_10, readLine(client));
        int port = server.port();
        server.close();
        assertClosedByPeer(client, "the client");
        assertThrows(ConnectException.class, () -> new Socket(InetAddress.getLoopbackAddress(), port).close());
        server.close(); // twice is harmless
    }

    @Test
    void aClientWhoseThreadCannotStartIsDroppedAndTheNextIsServed() throws IOException {
        AtomicBoolean failedOnce = new AtomicBoolean();
        try (LogCapture log = LogCapture.of("org.usarsim.wss.world", null);
                WorldServer failing = new WorldServer(world, new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), () -> seconds,
                client -> {
                    if (failedOnce.compareAndSet(false, true)) {
                        throw new OutOfMemoryError("unable to create native thread");
                    }
                    client.start();
                })) {
            Socket dropped = connect(failing.port());
            assertClosedByPeer(dropped, "the client whose thread could not start");
            String warning = "cannot serve client 127.0.0.1:" + dropped.getLocalPort()
                    + " (java.lang.OutOfMemoryError: unable to create native thread): dropped it; accepting the next";
            Wait.until("the server logs the dropped client", () -> has(log.records, Level.WARNING, warning));
            assertEquals(0, failing.clientCount(), "the dropped client is forgotten");

            Socket next = connect(failing.port());
            send(next, "GETPOS\r\n");
            assertEquals(AT_10, readLine(next), "the acceptor goes on");
            assertEquals(1, failing.clientCount());
        }
    }

    @Test
    void anotherVirtualMachineErrorStopsListeningAndCloseStillClosesTheClients() throws IOException {
        AtomicInteger starts = new AtomicInteger();
        WorldServer failing = new WorldServer(world, new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), () -> seconds,
                client -> {
                    if (starts.incrementAndGet() == 2) {
                        throw new InternalError("a test's");
                    }
                    client.start();
                });
        try {
            int port = failing.port();
            Socket served = connect(port);
            send(served, "GETPOS\r\n");
            assertEquals(AT_10, readLine(served));
            Socket dropped = connect(port);
            assertClosedByPeer(dropped, "the client whose start failed");
            Wait.until("the server stops listening", () -> refuses(port));
            send(served, "GETPOS\r\n");
            assertEquals(AT_10, readLine(served), "a client already served still is");
            failing.close();
            assertClosedByPeer(served, "the served client, at close()");
        } finally {
            failing.close();
        }
    }

    // ---- helpers ----

    private static boolean refuses(int port) {
        try (Socket probe = new Socket(InetAddress.getLoopbackAddress(), port)) {
            return false;
        } catch (IOException e) {
            return e instanceof ConnectException;
        }
    }

    private static boolean has(List<LogRecord> records, Level level, String message) {
        return records.stream().anyMatch(r -> r.getLevel().equals(level) && r.getMessage().equals(message));
    }

    private static String messages(List<LogRecord> records) {
        return records.stream().map(r -> r.getLevel() + " " + r.getMessage()).toList().toString();
    }

    private Socket connect() throws IOException {
        return connect(server.port());
    }

    private Socket connect(int port) throws IOException {
        Socket socket = new Socket();
        sockets.add(socket);
        socket.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), TIMEOUT_MS);
        socket.setSoTimeout(TIMEOUT_MS);
        socket.setTcpNoDelay(true);
        return socket;
    }
}
