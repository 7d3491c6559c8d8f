package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.BindException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/**
 * wss.portMemory and wss.maxPortsPerRobot: what a robot that leaves, or one that asks for many
 * ports, leaves behind. Over real sockets; descriptors and threads read from this process. The
 * memory's rule with the clock moved by hand (a robot back within it, one gone longer): RobotGoneTest.
 */
@Tag("slow")
class PortMemoryTest {

    private final List<AutoCloseable> toClose = new ArrayList<>();
    private final LogCapture log = LogCapture.of(Hub.class.getName(), Level.INFO);

    @AfterEach
    void stop() throws Exception {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            toClose.get(i).close();
        }
        log.close();
    }

    private TestHub hub(int portMemorySeconds, int maxPortsPerRobot) throws Exception {
        TestHub server = new TestHub(new NoopPropagationModel(), TestHub.config(true, 65536, portMemorySeconds, maxPortsPerRobot, 30));
        toClose.add(server);
        return server;
    }

    private TestRobot robot(TestHub server, String name, int... ports) throws Exception {
        TestRobot robot = connected(server);
        robot.init(name, ports);
        return robot;
    }

    /** A robot's control connection, not registered yet; closed after the test. */
    private TestRobot connected(TestHub server) throws Exception {
        TestRobot robot = server.robot();
        toClose.add(robot);
        return robot;
    }

    @Test
    void zeroForgetsAtOnceButNotWhileAConnectionIsOpen() throws Exception {
        TestHub server = hub(0, 1000);
        TestRobot r1 = connected(server);
        ServerSocket r1Accepts = r1.initAccepting("R1");
        TestRobot r2 = robot(server, "R2", 6000);
        TestRobot r3 = robot(server, "R3", 7000);
        int r2ToR1 = r2.dns("R1", 0);
        int r3ToR1 = r3.dns("R1", 0);
        Socket source = r2.connect(r2ToR1);
        toClose.add(source);
        Socket target = r1Accepts.accept();
        toClose.add(target);

        r1.control.close();
        Wait.until("R1 is deregistered", () -> !server.hub.getListOfRegisteredRobots().contains("R1"));
        Wait.until("the forgetting said (after the hub's lock, with its events)",
                () -> log.count(Level.INFO, "forgot 1 WSS port of R1, gone for 0 s") == 1);
        assertFree(r3ToR1);
        assertTaken(r2ToR1);

        source.close();
        Sockets.assertClosedByPeer(target, "the target once the source closed");
        target.close();
        Wait.until("the port of the closed connection is forgotten", () -> log.count(Level.INFO, "forgot 1 WSS port of R1") == 2);
        assertFree(r2ToR1);
    }

    /**
     * A robot that left has its ports forgotten once the hub's clock has passed wss.portMemory
     * (600 s here), moved by hand, without waiting for the machine's time (the rule's own
     * moments: RobotGoneTest).
     */
    @Test
    void aLeftRobotsPortsAreForgottenWhenTheHubsClockPassesThePortMemory() throws Exception {
        ManualHubClock clock = new ManualHubClock();
        TestHub server = new TestHub(new NoopPropagationModel(), TestHub.config(true, 65536, 600, 1000, 30), clock);
        toClose.add(server);
        TestRobot r1 = connected(server);
        r1.initAccepting("R1");
        TestRobot r2 = robot(server, "R2", 6000);
        int r2ToR1 = r2.dns("R1", 0);

        r1.control.close();
        Wait.until("R1 is deregistered", () -> !server.hub.getListOfRegisteredRobots().contains("R1"));
        clock.advance(Duration.ofSeconds(599));
        assertTrue(server.hub.snapshot().ports().stream().anyMatch(port -> port.wssPort() == r2ToR1), "remembered after 599 s");
        assertTaken(r2ToR1);
        assertEquals(0, log.count(Level.INFO, "forgot"), log.toString());

        clock.advance(Duration.ofSeconds(1));
        Wait.until("the port forgotten once the hub's clock says R1 is gone for 600 s",
                () -> log.count(Level.INFO, "forgot 1 WSS port of R1, gone for 600 s") == 1);
        assertFree(r2ToR1);
    }

    /**
     * 200 robots with fresh names come, get a WSS port each way (a few forward a connection) and
     * leave: once their ports are forgotten, this process has as many descriptors and threads as
     * before.
     */
    @Test
    void afterChurnDescriptorsAndThreadsReturnToTheirStartingLevel() throws Exception {
        TestHub server = hub(1, 1000);
        TestRobot peer = connected(server);
        ServerSocket accepts = peer.initAccepting("Peer");
        accepts.setSoTimeout(0);
        Thread sink = new Thread(() -> drain(accepts), "peer sink");
        sink.setDaemon(true);
        sink.start();

        churn(server, peer, "warm-up", 5); // loads every class and starts every lazy thread once
        Wait.until("the warm-up's ports are forgotten", () -> log.count(Level.INFO, "WSS ports of warm-up") == 5);
        Wait.until("the warm-up's link has ended", () -> Sockets.linkThreads() == 0);
        long descriptors = descriptors();
        long threads = threads();

        churn(server, peer, "churn", 200);
        long peak = descriptors();
        // Robots whose ports the hub still holds after the peak was read held them at the peak too.
        long held = server.hub.snapshot().ports().stream().filter(port -> port.from().startsWith("churn"))
                .map(HubSnapshot.PortEntry::from).distinct().count();
        // Each gone robot not yet forgotten holds two descriptors; the bound asks for one each, since
        // another test's leftover descriptors may close during the churn (seen: one short of two each).
        assertTrue(peak >= descriptors + held,
                "at least one descriptor per gone robot not yet forgotten (" + held + "): " + descriptors + " -> " + peak);

        // The hub's snapshot, not the log: the "forgot" lines are limited per kind (docs/reliability.md).
        Wait.until("every churned robot's ports are forgotten", () -> server.hub.snapshot().ports().stream()
                .noneMatch(port -> port.from().startsWith("churn") || port.to().startsWith("churn")));
        // At most the starting level (other tests' leftovers may end meanwhile, never ours start).
        long descriptorsAfter = Wait.settle("descriptors back", PortMemoryTest::descriptors, n -> n <= descriptors);
        assertTrue(descriptorsAfter <= descriptors, "descriptors: " + descriptors + " -> " + peak + " -> " + descriptorsAfter);
        long threadsAfter = Wait.settle("threads back", PortMemoryTest::threads, n -> n <= threads);
        assertTrue(threadsAfter <= threads, "threads: " + threads + " -> " + threadsAfter);
        accepts.close();
    }

    /** Robots come, get a WSS port each way (every tenth forwards a connection), and leave. */
    private static void churn(TestHub server, TestRobot peer, String prefix, int count) throws Exception {
        for (int i = 0; i < count; i++) {
            try (TestRobot robot = server.robot()) {
                robot.init(prefix + i, 5000);
                int toPeer = robot.dns("Peer", 0);
                peer.dns(prefix + i, 0);
                if (i % 10 == 0) {
                    try (Socket data = robot.connect(toPeer)) {
                        Sockets.send(data, "hello");
                        data.shutdownOutput();
                        Sockets.assertClosedByPeer(data, "the connection through the WSS");
                    }
                }
            }
        }
    }

    /** The peer's accepting socket: reads each connection to its end and closes it. */
    private static void drain(ServerSocket accepts) {
        while (!accepts.isClosed()) {
            try (Socket connection = accepts.accept()) {
                connection.getInputStream().readAllBytes();
            } catch (IOException e) {
                // closed at the end of the test, or one connection failed: the test asserts the rest
            }
        }
    }

    @Test
    void aRobotGetsAtMostMaxPortsPerRobotAsSourceAndTheOthersGoOn() throws Exception {
        TestHub server = hub(600, 3);
        TestRobot r1 = robot(server, "R1", 5000);
        TestRobot r2 = robot(server, "R2", 5000, 5001, 5002, 5003);
        robot(server, "R3", 5000);
        int first = r1.dns("R2", 5000);
        r1.dns("R2", 5001);
        r1.dns("R3", 0);
        assertEquals("ERROR {Reason Could.Not.Allocate.Port}", r1.ask("DNS {Robot R2} {Port 5002}"));
        Wait.until("the refusal said (after the hub's lock, with its events)",
                () -> log.count(Level.WARNING, "R1 holds 3 WSS ports as source, the most wss.maxPortsPerRobot allows") == 1);
        assertEquals(first, r1.dns("R2", 5000), "a port it holds is still answered");
        r2.dns("R1", 0);
        r2.dns("R3", 0);
        assertTrue(r1.ask("GETSS {Robot R2}").startsWith("SS {Robot R2} {Strength "), "R1's control connection stays usable");
    }

    private static void assertTaken(int port) {
        assertThrows(BindException.class, () -> bind(port), "WSS port " + port + " is still held");
    }

    private static void assertFree(int port) throws IOException {
        bind(port);
    }

    private static void bind(int port) throws IOException {
        try (ServerSocket socket = new ServerSocket()) {
            socket.setReuseAddress(false);
            socket.bind(new InetSocketAddress("127.0.0.1", port));
        }
    }

    private static long descriptors() {
        try (Stream<Path> open = Files.list(Path.of("/proc/self/fd"))) {
            return open.count();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * The JVM's threads but the warnings' summary thread: the churn's "allocated" and "forgot" lines
     * are over the INFO limit, and that thread lives until their summary is written, a minute later
     * (docs/reliability.md); it is one thread whatever the churn, not one the churn leaves behind.
     */
    private static long threads() {
        return Thread.getAllStackTraces().keySet().stream().filter(thread -> !thread.getName().equals("wss-warnings")).count();
    }
}
