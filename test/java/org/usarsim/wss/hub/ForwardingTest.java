package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.usarsim.wss.hub.Sockets.assertClosedByPeer;
import static org.usarsim.wss.hub.Sockets.linkThreads;
import static org.usarsim.wss.hub.Sockets.randomBytes;
import static org.usarsim.wss.hub.Sockets.readExactly;
import static org.usarsim.wss.hub.Sockets.readExactlyBytes;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.ConnectException;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** WSS ports and forwarding over real loopback sockets, replaying how team clients use them. */
class ForwardingTest {

    private TestHub server;
    private final ExecutorService pool = Executors.newCachedThreadPool();

    @BeforeEach
    void start() throws Exception {
        server = new TestHub();
    }

    @AfterEach
    void stop() throws Exception {
        server.close();
        pool.shutdownNow();
        assertTrue(pool.awaitTermination(5, TimeUnit.SECONDS));
    }

    @Test
    void dnsIsStableAndOnePortPerDirectionAndTargetPort() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            r1.init("R1", 5000, 5001);
            r2.init("R2", 6000);
            int toR1 = r2.dns("R1", 0);
            int toR1Second = r2.dns("R1", 5001);
            int toR2 = r1.dns("R2", 0);
            assertNotEquals(toR1, toR2, "one port each way");
            assertNotEquals(toR1, toR1Second, "one port per target port");
            for (int i = 0; i < 5; i++) {
                assertEquals(toR1, r2.dns("R1", 0));
                assertEquals(toR1, r2.dns("R1", 5000));
                assertEquals(toR2, r1.dns("R2", 6000));
                assertEquals(toR1Second, r2.dns("R1", 5001));
            }
        }
    }

    @Test
    void bytesFlowBothWaysAndReverseDnsNamesTheSource() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); TestRobot r3 = server.robot()) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            r3.init("R3", 7000);
            try (Socket fromR2 = r2.connect(r2.dns("R1", 0)); Socket atR1 = r1Accepts.accept()) {
                atR1.setSoTimeout(TestRobot.TIMEOUT_MS);
                fromR2.getOutputStream().write("hello R1".getBytes(StandardCharsets.UTF_8));
                assertEquals("hello R1", readExactly(atR1.getInputStream(), 8));
                atR1.getOutputStream().write("hi R2!".getBytes(StandardCharsets.UTF_8));
                assertEquals("hi R2!", readExactly(fromR2.getInputStream(), 6));

                int peerPort = atR1.getPort();
                assertEquals("REVERSEDNSREPLY {Port " + peerPort + "} {Robot R2}", r1.ask("REVERSEDNS {Port " + peerPort + "}"));
                assertEquals("REVERSEDNSREPLY {Port " + peerPort + "} {Error UnknownOrIllegalPort}",
                        r3.ask("REVERSEDNS {Port " + peerPort + "}"), "only the target may ask");
                assertEquals("REVERSEDNSREPLY {Port " + peerPort + "} {Error UnknownOrIllegalPort}",
                        r2.ask("REVERSEDNS {Port " + peerPort + "}"), "not the source either");
            }
        }
    }

    @Test
    void twoSimultaneousBinaryStreamsOnOneWssPort() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            int port = r2.dns("R1", 0);
            Socket a = r2.connect(port);
            Socket atR1First = r1Accepts.accept();
            Socket b = r2.connect(port);
            Socket atR1Second = r1Accepts.accept();
            List<Future<byte[]>> received = new ArrayList<>();
            List<byte[]> sent = new ArrayList<>();
            int size = 3 * 1024 * 1024 + 17;
            Socket[][] pairs = {{a, atR1First}, {atR1First, a}, {b, atR1Second}, {atR1Second, b}};
            for (int i = 0; i < pairs.length; i++) {
                byte[] data = randomBytes(size, i);
                sent.add(data);
                Socket from = pairs[i][0];
                Socket to = pairs[i][1];
                pool.submit(() -> {
                    from.getOutputStream().write(data);
                    return null;
                });
                received.add(pool.submit(() -> readExactlyBytes(to.getInputStream(), size)));
            }
            for (int i = 0; i < pairs.length; i++) {
                assertArrayEquals(sent.get(i), received.get(i).get(30, TimeUnit.SECONDS), "stream " + i);
            }
            for (Socket socket : new Socket[] {a, b, atR1First, atR1Second}) {
                socket.close();
            }
            r1Accepts.close();
        }
        Wait.until("every link thread ended", () -> linkThreads() == 0);
    }

    @Test
    void oneConnectionPerPacketFiftyInARow() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            for (int i = 0; i < 50; i++) {
                byte[] packet = ("packet " + i + " " + "#".repeat(i * 37)).getBytes(StandardCharsets.UTF_8);
                int port = r2.dns("R1", 0);
                try (Socket out = r2.connect(port)) {
                    out.getOutputStream().write(packet);
                }
                try (Socket in = r1Accepts.accept()) {
                    in.setSoTimeout(TestRobot.TIMEOUT_MS);
                    int peerPort = in.getPort();
                    String reply = r1.ask("REVERSEDNS {Port " + peerPort + "}");
                    // The link may already have been closed by the source's end of stream: both are true answers.
                    assertTrue(reply.equals("REVERSEDNSREPLY {Port " + peerPort + "} {Robot R2}")
                            || reply.equals("REVERSEDNSREPLY {Port " + peerPort + "} {Error UnknownOrIllegalPort}"), reply);
                    assertArrayEquals(packet, in.getInputStream().readAllBytes(), "packet " + i);
                }
            }
            r1Accepts.close();
        }
        Wait.until("every link thread ended", () -> linkThreads() == 0);
    }

    @Test
    void reverseDnsAnswersForEveryOpenConnection() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); TestRobot r3 = server.robot()) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            r3.init("R3", 7000);
            List<Socket> sockets = new ArrayList<>();
            for (int i = 0; i < 10; i++) {
                TestRobot source = i % 2 == 0 ? r2 : r3;
                sockets.add(source.connect(source.dns("R1", 0)));
                Socket accepted = r1Accepts.accept();
                sockets.add(accepted);
                String expected = i % 2 == 0 ? "R2" : "R3";
                assertEquals("REVERSEDNSREPLY {Port " + accepted.getPort() + "} {Robot " + expected + "}",
                        r1.ask("REVERSEDNS {Port " + accepted.getPort() + "}"));
            }
            for (Socket socket : sockets) {
                socket.close();
            }
            r1Accepts.close();
        }
    }

    @Test
    void endOfStreamClosesBothSidesAfterDeliveringWhatWasRead() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            byte[] data = randomBytes(2 * 1024 * 1024, 99);
            Socket out = r2.connect(r2.dns("R1", 0));
            try (Socket in = r1Accepts.accept()) {
                in.setSoTimeout(TestRobot.TIMEOUT_MS);
                Future<byte[]> all = pool.submit(() -> in.getInputStream().readAllBytes());
                out.getOutputStream().write(data);
                out.close();
                assertArrayEquals(data, all.get(30, TimeUnit.SECONDS), "everything, then end of stream");
            }
            // And the other way: the target closes, the source sees what was sent and then the end.
            Socket source = r2.connect(r2.dns("R1", 0));
            source.setSoTimeout(TestRobot.TIMEOUT_MS);
            try (Socket target = r1Accepts.accept()) {
                target.getOutputStream().write("bye".getBytes(StandardCharsets.UTF_8));
            }
            assertEquals("bye", new String(source.getInputStream().readAllBytes(), StandardCharsets.UTF_8));
            source.close();
            r1Accepts.close();
        }
        Wait.until("every link thread ended", () -> linkThreads() == 0);
    }

    @Test
    void aSideThatClosesStillGetsEverythingToTheOtherWhileThatOneKeepsTalking() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            byte[] data = randomBytes(6 * 1024 * 1024, 7);
            Socket out = r2.connect(r2.dns("R1", 0));
            try (Socket in = r1Accepts.accept()) {
                in.setSoTimeout(TestRobot.TIMEOUT_MS);
                // R2 sends a big message and ends its stream (reading what comes until its end, as a
                // client that closes cleanly does); R1 keeps sending heartbeats the link no longer reads.
                pool.submit(() -> {
                    out.getInputStream().transferTo(java.io.OutputStream.nullOutputStream());
                    out.close();
                    return null;
                });
                pool.submit(() -> {
                    out.getOutputStream().write(data);
                    out.shutdownOutput();
                    return null;
                });
                java.util.concurrent.atomic.AtomicBoolean reading = new java.util.concurrent.atomic.AtomicBoolean(true);
                pool.submit(() -> {
                    byte[] heartbeat = new byte[16];
                    while (reading.get()) {
                        in.getOutputStream().write(heartbeat);
                        Thread.yield();
                    }
                    return null;
                });
                ByteArrayOutputStream received = new ByteArrayOutputStream();
                byte[] small = new byte[1024];
                int read;
                while ((read = in.getInputStream().read(small)) >= 0) {
                    received.write(small, 0, read);
                }
                reading.set(false);
                assertArrayEquals(data, received.toByteArray(), "everything R2 sent, then end of stream (no reset)");
            }
            r1Accepts.close();
        }
        Wait.until("every link thread ended", () -> linkThreads() == 0);
    }

    @Test
    void aTargetThatDoesNotListenGetsTheSourceClosedAtOnce() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            ServerSocket closed = r1.listen();
            int deadPort = closed.getLocalPort();
            closed.close();
            r1.init("R1", deadPort);
            r2.init("R2", 6000);
            int port = r2.dns("R1", 0);
            for (int i = 0; i < 3; i++) {
                try (Socket out = r2.connect(port)) {
                    assertClosedByPeer(out, "connection " + i + " to a target that does not listen");
                }
            }
            assertEquals("SS {Robot R1} {Strength 0}", r2.ask("GETSS {Robot R1}"), "the robots are still served");
        }
    }

    @Test
    void aRobotThatRegisteredFrom127002IsReachedThereOnly() throws Exception {
        try (TestRobot r1 = server.robotAt("127.0.0.2"); TestRobot r2 = server.robot()) {
            ServerSocket r1Accepts = r1.listen();
            assertEquals("127.0.0.2", r1Accepts.getInetAddress().getHostAddress());
            r1.init("R1", r1Accepts.getLocalPort());
            ServerSocket r2Accepts = r2.initAccepting("R2");
            try (Socket out = r2.connect(r2.dns("R1", 0)); Socket in = r1Accepts.accept()) {
                in.setSoTimeout(TestRobot.TIMEOUT_MS);
                out.getOutputStream().write("to .2".getBytes(StandardCharsets.UTF_8));
                assertEquals("to .2", readExactly(in.getInputStream(), 5));
            }
            // And back: R1 connects from 127.0.0.2, the address it registered from.
            try (Socket out = r1.connect(r1.dns("R2", 0)); Socket in = r2Accepts.accept()) {
                in.setSoTimeout(TestRobot.TIMEOUT_MS);
                in.getOutputStream().write("to .1".getBytes(StandardCharsets.UTF_8));
                assertEquals("to .1", readExactly(out.getInputStream(), 5));
            }
        }
    }

    @Test
    void aConnectionFromAnotherAddressThanTheSourceRobotsIsClosed() throws Exception {
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); TestRobot stranger = server.robotAt("127.0.0.3")) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            int port = r2.dns("R1", 0);
            try (Socket fromStranger = stranger.connect(port)) {
                assertClosedByPeer(fromStranger, "a connection from 127.0.0.3");
            }
            try (Socket out = r2.connect(port); Socket in = r1Accepts.accept()) {
                assertEquals("R2", reverseDnsName(r1, in.getPort()));
            }
        }
    }

    @Test
    void withoutTheAddressCheckAnyAddressIsForwarded() throws Exception {
        server.close();
        server = new TestHub(new org.usarsim.wss.model.noop.NoopPropagationModel(), false, 65536);
        try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot(); TestRobot stranger = server.robotAt("127.0.0.3")) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            try (Socket out = stranger.connect(r2.dns("R1", 0)); Socket in = r1Accepts.accept()) {
                in.setSoTimeout(TestRobot.TIMEOUT_MS);
                out.getOutputStream().write("x".getBytes(StandardCharsets.UTF_8));
                assertEquals("x", readExactly(in.getInputStream(), 1));
            }
        }
    }

    @Test
    void afterControlLossTheSameNameGetsTheSamePortsBack() throws Exception {
        try (TestRobot r2 = server.robot()) {
            TestRobot r1 = server.robot();
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            int port = r2.dns("R1", 0);
            r1.control.close();
            Wait.until("R1 is deregistered", () -> !server.hub.getListOfRegisteredRobots().contains("R1"));
            assertThrows(ConnectException.class, () -> r2.connect(port).close(), "no target: the port does not listen");
            try (TestRobot again = server.robot()) {
                again.init("R1", r1Accepts.getLocalPort());
                assertEquals(port, r2.dns("R1", 0));
                try (Socket out = r2.connect(port); Socket in = r1Accepts.accept()) {
                    in.setSoTimeout(TestRobot.TIMEOUT_MS);
                    out.getOutputStream().write("back".getBytes(StandardCharsets.UTF_8));
                    assertEquals("back", readExactly(in.getInputStream(), 4));
                }
            }
            r1.close();
        }
    }

    // ---- helpers ----

    private static String reverseDnsName(TestRobot asker, int port) throws IOException {
        String reply = asker.ask("REVERSEDNS {Port " + port + "}");
        String prefix = "REVERSEDNSREPLY {Port " + port + "} {Robot ";
        assertTrue(reply.startsWith(prefix), reply);
        return reply.substring(prefix.length(), reply.length() - 1);
    }
}
