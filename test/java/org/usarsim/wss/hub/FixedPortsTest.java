package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.core.DeclaredRobot;
import org.usarsim.wss.hub.core.FixedPort;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.PortKey;
import org.usarsim.wss.hub.core.UdpCounts;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/** Declared robots and fixed ports over real sockets on 127.0.0.1 (docs/fixed-ports.md): generous bounds, no timing asserted. */
@Tag("slow")
class FixedPortsTest {

    private static final InetAddress LOCAL = InetAddress.getLoopbackAddress();

    private static TestHub hub(FixedPort... ports) throws Exception {
        HubConfig config = TestHub.config(true, 65536, 600, 1000, 30).withFixed(new FixedSetup(
                List.of(new DeclaredRobot("Base", LOCAL), new DeclaredRobot("Scout", LOCAL)), List.of(ports), 60));
        return new TestHub(new NoopPropagationModel(), config);
    }

    @Test
    void aFixedTcpPortForwardsIsBrokenByAForceAndAcceptsAgainOnTheSameNumber() throws Exception {
        try (ServerSocket base = new ServerSocket(0, 50, LOCAL)) {
            int number = Sockets.freeTcp();
            try (TestHub test = hub(new FixedPort(FixedPort.Transport.TCP, new PortKey("Scout", "Base", base.getLocalPort()), number))) {
                assertEquals(List.of("Base", "Scout"), test.hub.getListOfRegisteredRobots());
                byte[] sent = new byte[1 << 20];
                new Random(1).nextBytes(sent);
                try (Socket scout = new Socket(LOCAL, number); Socket atBase = base.accept()) {
                    scout.getOutputStream().write(sent);
                    byte[] got = new byte[sent.length];
                    new DataInputStream(atBase.getInputStream()).readFully(got);
                    assertArrayEquals(sent, got);
                    atBase.getOutputStream().write("ok".getBytes());
                    byte[] answer = new byte[2];
                    new DataInputStream(scout.getInputStream()).readFully(answer);
                    assertEquals("ok", new String(answer));
                    Wait.until("the bytes counted", () -> test.hub.snapshot().pairs().stream()
                            .anyMatch(pair -> pair.bytesFirstToSecond() == 2 && pair.bytesSecondToFirst() == sent.length));
                    assertTrue(test.hub.snapshot().ports().stream().anyMatch(port -> port.wssPort() == number && port.listening()));

                    test.hub.force("Scout", "Base", Force.DOWN);
                    InputStream in = scout.getInputStream();
                    scout.setSoTimeout(5000);
                    assertEquals(-1, readOrEnd(in), "the connection closes as the pair breaks");
                }
                assertThrows(IOException.class, () -> new Socket(LOCAL, number).close(), "refused while broken");
                test.hub.release("Scout", "Base");
                Wait.until("the fixed port listens again", () -> test.hub.snapshot().ports().stream()
                        .anyMatch(port -> port.wssPort() == number && port.listening()));
                try (Socket again = new Socket(LOCAL, number); Socket atBase = base.accept()) {
                    again.getOutputStream().write(7);
                    assertEquals(7, atBase.getInputStream().read());
                }
            }
        }
    }

    private static int readOrEnd(InputStream in) throws IOException {
        try {
            return in.read();
        } catch (IOException e) {
            return -1; // reset: closed all the same
        }
    }

    @Test
    void aDeclaredRobotsNameIsTakenForAnInit() throws Exception {
        try (TestHub test = hub(); TestRobot robot = test.robot()) {
            String reply = robot.ask("INIT {Robot Scout} {Port 7000}");
            assertTrue(reply.contains("Robot.Alread.Exists"), reply);
        }
    }

    @Test
    void aFixedUdpPortRelaysBothWaysPerSenderAndDropsWhileBroken() throws Exception {
        try (DatagramSocket base = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
            int number = Sockets.freeUdp();
            try (TestHub test = hub(new FixedPort(FixedPort.Transport.UDP, new PortKey("Scout", "Base", base.getLocalPort()), number));
                    DatagramSocket scout = new DatagramSocket(new InetSocketAddress(LOCAL, 0));
                    DatagramSocket second = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
                test.hub.addListener(new org.usarsim.wss.model.WssEventListener() {
                    @Override
                    public void udpCounted(String from, String to, int fixedPort, long datagrams, long bytes, long droppedBroken,
                            long droppedQueue, long lost) {
                        if (from.equals("Scout")) {
                            reported.add(new long[] {datagrams, bytes, droppedQueue, lost, droppedBroken});
                        }
                    }
                });
                base.setSoTimeout(5000);
                scout.setSoTimeout(5000);
                second.setSoTimeout(5000);
                byte[] largest = new byte[65_507];
                new Random(2).nextBytes(largest);
                scout.send(new DatagramPacket(largest, largest.length, LOCAL, number));
                DatagramPacket got = new DatagramPacket(new byte[65_536], 65_536);
                base.receive(got);
                assertEquals(65_507, got.getLength(), "carried whole");
                assertArrayEquals(largest, java.util.Arrays.copyOf(got.getData(), got.getLength()));
                InetSocketAddress scoutsSession = (InetSocketAddress) got.getSocketAddress();
                base.send(new DatagramPacket("back".getBytes(), 4, scoutsSession));
                DatagramPacket answer = new DatagramPacket(new byte[100], 100);
                scout.receive(answer);
                assertEquals("back", new String(answer.getData(), 0, answer.getLength()));
                assertEquals(number, answer.getPort(), "from the fixed port");

                second.send(new DatagramPacket("two".getBytes(), 3, LOCAL, number));
                base.receive(got);
                assertTrue(!got.getSocketAddress().equals(scoutsSession), "another sender, another session socket");

                test.hub.force("Scout", "Base", Force.DOWN);
                Wait.until("the pair down", () -> test.hub.snapshot().pairs().stream().anyMatch(pair -> !pair.state().name().equals("UP")));
                scout.send(new DatagramPacket("lost".getBytes(), 4, LOCAL, number));
                UdpCounts.Reading[] counts = new UdpCounts.Reading[1];
                Wait.until("the datagram dropped and counted", () -> {
                    counts[0] = udp(test, "Scout");
                    return counts[0].droppedBroken() == 1;
                });
                assertEquals(2, counts[0].datagrams());
                assertEquals(65_507 + 3, counts[0].bytes());
                base.setSoTimeout(300);
                assertThrows(SocketTimeoutException.class, () -> base.receive(new DatagramPacket(new byte[10], 10)));
                Wait.until("the event log's listeners told, within a second or so", () -> reported.stream().mapToLong(r -> r[4]).sum() == 1
                        && reported.stream().mapToLong(r -> r[0]).sum() == 2);
            }
        }
    }

    /**
     * Issue 36: two fixed UDP ports of one pair, ten datagrams to the first: the listeners (the event
     * log, the recording) are told ten datagrams, each report naming the port they went through, and
     * the table says ten. Before, each relay reported the pair's counts: twenty, and no port.
     */
    @Test
    void twoFixedUdpPortsOfAPairEachReportTheirOwnDatagrams() throws Exception {
        try (DatagramSocket base = new DatagramSocket(new InetSocketAddress(LOCAL, 0));
                DatagramSocket baseToo = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
            int first = Sockets.freeUdp();
            int second = Sockets.freeUdp();
            while (second == first) {
                second = Sockets.freeUdp();
            }
            java.util.List<String> reports = new java.util.concurrent.CopyOnWriteArrayList<>();
            try (TestHub test = hub(new FixedPort(FixedPort.Transport.UDP, new PortKey("Scout", "Base", base.getLocalPort()), first),
                    new FixedPort(FixedPort.Transport.UDP, new PortKey("Scout", "Base", baseToo.getLocalPort()), second));
                    DatagramSocket scout = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
                test.hub.addListener(new org.usarsim.wss.model.WssEventListener() {
                    @Override
                    public void udpCounted(String from, String to, int fixedPort, long datagrams, long bytes, long droppedBroken,
                            long droppedQueue, long lost) {
                        reports.add(from + "," + to + "," + fixedPort + "," + datagrams + "," + bytes);
                    }
                });
                base.setSoTimeout(5000);
                for (int i = 0; i < 10; i++) {
                    scout.send(new DatagramPacket(new byte[2], 2, LOCAL, first));
                    base.receive(new DatagramPacket(new byte[10], 10));
                }
                Wait.until("the table says ten", () -> udp(test, "Scout").datagrams() == 10);
                Wait.until("ten datagrams reported", () -> reports.stream().mapToLong(r -> Long.parseLong(r.split(",")[3])).sum() >= 10);
                assertEquals(10, udp(test, "Scout").datagrams());
                assertEquals(10, reports.stream().mapToLong(r -> Long.parseLong(r.split(",")[3])).sum(), reports.toString());
                assertTrue(reports.stream().allMatch(r -> r.startsWith("Scout,Base," + first + ",")), reports.toString());
            }
            assertEquals(10, reports.stream().mapToLong(r -> Long.parseLong(r.split(",")[3])).sum(), "none more at the stop: " + reports);
        }
    }

    /** Base - Scout's UDP counts from Scout to Base ("Base" is the pair's first name). */
    @Test
    void aShapedFixedUdpPortLosesWhatTheLossTableSaysAndCountsIt() throws Exception {
        try (DatagramSocket base = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
            int number = Sockets.freeUdp();
            HubConfig config = TestHub.config(true, 65536, 600, 1000, 30)
                    .withShaping(new org.usarsim.wss.shaping.ShapingConfig(true, org.usarsim.wss.shaping.RateTable.DEFAULT, 2, true, org.usarsim.wss.shaping.ShapingConfig.DEFAULT_QUEUE_MS,
                            org.usarsim.wss.shaping.LossTable.parse("0:100")), Map.of())
                    .withFixed(new FixedSetup(List.of(new DeclaredRobot("Base", LOCAL), new DeclaredRobot("Scout", LOCAL)),
                            List.of(new FixedPort(FixedPort.Transport.UDP, new PortKey("Scout", "Base", base.getLocalPort()), number)), 60));
            try (TestHub test = new TestHub(new NoopPropagationModel(), config);
                    DatagramSocket scout = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
                for (int i = 0; i < 5; i++) {
                    scout.send(new DatagramPacket(new byte[100], 100, LOCAL, number));
                }
                Wait.until("five datagrams lost to the signal (the Noop model's 0 dBm, a table of 100 % at 0 dBm)",
                        () -> udp(test, "Scout").lost() == 5);
                assertEquals(0, udp(test, "Scout").datagrams());
                base.setSoTimeout(300);
                assertThrows(SocketTimeoutException.class, () -> base.receive(new DatagramPacket(new byte[200], 200)));
            }
        }
    }

    @Test
    void aShapedFixedUdpPortLosesWhatTheModelsOwnRuleSaysInsteadOfTheTable() throws Exception {
        try (DatagramSocket base = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
            int number = Sockets.freeUdp();
            HubConfig config = TestHub.config(true, 65536, 600, 1000, 30)
                    .withShaping(new org.usarsim.wss.shaping.ShapingConfig(true, org.usarsim.wss.shaping.RateTable.DEFAULT, 2, true,
                            org.usarsim.wss.shaping.ShapingConfig.DEFAULT_QUEUE_MS, org.usarsim.wss.shaping.LossTable.parse("0:100")), Map.of())
                    .withFixed(new FixedSetup(List.of(new DeclaredRobot("Base", LOCAL), new DeclaredRobot("Scout", LOCAL)),
                            List.of(new FixedPort(FixedPort.Transport.UDP, new PortKey("Scout", "Base", base.getLocalPort()), number)), 60));
            org.usarsim.wss.model.DatagramLoss largeOnesLost = (bytes, nowNs, random) -> bytes > 100;
            org.usarsim.wss.model.StubModel model = new org.usarsim.wss.model.StubModel() {
                @Override
                public java.util.Optional<org.usarsim.wss.model.LinkQuality> linkQualityForPair(String from, String to) {
                    return java.util.Optional.of(new org.usarsim.wss.model.LinkQuality(54_000_000, 0, largeOnesLost));
                }
            };
            try (TestHub test = new TestHub(model, config); DatagramSocket scout = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
                Wait.until("the model's quality in the pair's condition (its rate, and with it its rule)", () -> test.hub.snapshot().pairs()
                        .stream().anyMatch(pair -> pair.linkRateFirstToSecond() == 54_000_000 && pair.linkRateSecondToFirst() == 54_000_000));
                for (int size : new int[] {100, 101, 50, 1000}) {
                    scout.send(new DatagramPacket(new byte[size], size, LOCAL, number));
                }
                Wait.until("two lost by the model's rule (the table would lose all four)",
                        () -> udp(test, "Scout").lost() == 2 && udp(test, "Scout").datagrams() == 2);
                base.setSoTimeout(5000);
                DatagramPacket got = new DatagramPacket(new byte[2000], 2000);
                base.receive(got);
                assertEquals(100, got.getLength());
                base.receive(got);
                assertEquals(50, got.getLength());
            }
        }
    }

    /**
     * Datagrams queued at a low rate take a raised one (issue 27): 20 of 1,000 bytes from Scout at
     * 16 kbit/s, half a second of airtime each; once the first arrived the pair is raised to
     * 54 Mbit/s. The two already booked keep their airtime, the 17 others go at the new rate: all
     * within a second or so, where at 16 kbit/s they would take 9.5 s more (before, the queue took
     * a new rate only with the next datagram that came in).
     */
    @Test
    void datagramsQueuedAtALowRateTakeARaisedRate() throws Exception {
        try (DatagramSocket base = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
            int number = Sockets.freeUdp();
            HubConfig config = TestHub.config(true, 65536, 600, 1000, 30)
                    .withShaping(new org.usarsim.wss.shaping.ShapingConfig(true, org.usarsim.wss.shaping.RateTable.DEFAULT, 0, true), Map.of())
                    .withFixed(new FixedSetup(List.of(new DeclaredRobot("Base", LOCAL), new DeclaredRobot("Scout", LOCAL)),
                            List.of(new FixedPort(FixedPort.Transport.UDP, new PortKey("Scout", "Base", base.getLocalPort()), number)), 60));
            try (TestHub test = new TestHub(new NoopPropagationModel(), config);
                    DatagramSocket scout = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
                test.hub.force("Scout", "Base", Force.UP, new org.usarsim.wss.hub.core.RatePin(16_000, 0));
                for (int i = 0; i < 20; i++) {
                    scout.send(new DatagramPacket(new byte[1000], 1000, LOCAL, number));
                }
                base.setSoTimeout(5000);
                DatagramPacket packet = new DatagramPacket(new byte[2000], 2000);
                base.receive(packet);
                long raised = System.nanoTime();
                test.hub.force("Scout", "Base", Force.UP, new org.usarsim.wss.hub.core.RatePin(54_000_000, 0));
                for (int i = 1; i < 20; i++) {
                    base.receive(packet);
                }
                double seconds = (System.nanoTime() - raised) / 1e9;
                System.out.printf(java.util.Locale.ROOT, "FixedPortsTest: 19 datagrams %.2f s after the raise%n", seconds);
                assertTrue(seconds < 4, "the 19 others " + seconds + " s after the raise: two at 16 kbit/s, 17 at 54 Mbit/s");
            }
        }
    }

    private final java.util.List<long[]> reported = new java.util.concurrent.CopyOnWriteArrayList<>();

    private static UdpCounts.Reading udp(TestHub test, String from) {
        HubSnapshot.PairEntry pair = test.hub.snapshot().pairs().get(0);
        return from.equals(pair.first()) ? pair.udpFirstToSecond() : pair.udpSecondToFirst();
    }
}
