package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * A robot that leaves right after sending loses nothing: the sequence of the original's own
 * stress client, over real sockets.
 */
class LeavingRobotTest {

    private static final int ROBOTS = 100;

    private final ExecutorService pool = Executors.newCachedThreadPool();
    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void stop() throws Exception {
        for (AutoCloseable closeable : toClose) {
            closeable.close();
        }
        pool.shutdownNow();
        assertTrue(pool.awaitTermination(5, TimeUnit.SECONDS));
    }

    /**
     * 100 robots in a row, each: INIT, DNS the peer, connect to the WSS port, send one line,
     * close that connection (every other robot only ends its sending half, to see the end of
     * stream come back), and at once close its control connection. The peer receives every line,
     * each followed by the end of stream.
     */
    @Test
    void aRobotThatLeavesRightAfterSendingLosesNothing() throws Exception {
        TestHub server = new TestHub();
        toClose.add(server);
        TestRobot peer = server.robotAt("127.0.0.2");
        toClose.add(peer);
        ServerSocket accepts = peer.initAccepting("Peer");
        Set<String> received = ConcurrentHashMap.newKeySet();
        Set<String> failures = ConcurrentHashMap.newKeySet();
        pool.submit(() -> receive(accepts, received, failures));

        List<Socket> halfClosed = new ArrayList<>();
        for (int i = 0; i < ROBOTS; i++) {
            TestRobot robot = server.robotAt("127.0.0.1");
            robot.init("S" + i);
            int wssPort = robot.dns("Peer", 0);
            Socket data = robot.connect(wssPort);
            Sockets.send(data, "line " + i + "\n");
            if (i % 2 == 0) {
                data.close();
            } else {
                data.shutdownOutput();
                halfClosed.add(data);
                toClose.add(data);
            }
            robot.control.close();
        }

        Wait.until("every line arrived (" + received.size() + " so far, failures " + failures + ")",
                () -> received.size() + failures.size() >= ROBOTS);
        assertEquals(Set.of(), failures, "connections at the peer without a line and its end of stream");
        Set<String> expected = new TreeSet<>();
        for (int i = 0; i < ROBOTS; i++) {
            expected.add("line " + i + "\n");
        }
        assertEquals(expected, new TreeSet<>(received));
        for (Socket data : halfClosed) {
            Sockets.assertClosedByPeer(data, "the sender's connection after the line was delivered");
        }
    }

    /**
     * The other way round: 100 target robots in a row, each registers, a stable source robot
     * connects to it through the WSS and sends a line, and the target closes its control
     * connection at once. The connection completed before the target left, so it is forwarded,
     * to the address and port the target registered, where its accepting socket still is.
     */
    @Test
    void aConnectionToARobotThatLeavesAtOnceIsStillForwarded() throws Exception {
        TestHub server = new TestHub();
        toClose.add(server);
        TestRobot source = server.robotAt("127.0.0.1");
        toClose.add(source);
        source.init("Source");
        for (int i = 0; i < ROBOTS; i++) {
            TestRobot target = server.robotAt("127.0.0.2");
            toClose.add(target);
            ServerSocket accepts = target.initAccepting("T" + i);
            try (Socket data = source.connect(source.dns("T" + i, 0))) {
                Sockets.send(data, "line " + i + "\n");
                data.shutdownOutput();
                target.control.close();
                try (Socket delivered = accepts.accept()) {
                    assertEquals("line " + i + "\n", new String(delivered.getInputStream().readAllBytes(), StandardCharsets.UTF_8),
                            "what T" + i + " received, up to the end of stream");
                }
                Sockets.assertClosedByPeer(data, "the source's connection to T" + i);
            }
        }
    }

    /** Accepts every connection and reads it to its end: what came before the end of stream is one entry. */
    private void receive(ServerSocket accepts, Set<String> received, Set<String> failures) {
        while (!accepts.isClosed()) {
            Socket connection;
            try {
                accepts.setSoTimeout(0);
                connection = accepts.accept();
            } catch (IOException e) {
                return;
            }
            pool.submit(() -> {
                try (Socket c = connection) {
                    c.setSoTimeout(TestRobot.TIMEOUT_MS);
                    String text = new String(c.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
                    if (!received.add(text)) {
                        failures.add("twice: " + text);
                    }
                } catch (IOException e) {
                    failures.add(e.toString());
                }
                return null;
            });
        }
    }
}
