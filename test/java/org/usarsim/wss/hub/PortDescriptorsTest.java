package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.StandardSocketOptions;
import java.nio.channels.NetworkChannel;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/**
 * What a WSS port costs (issue 18): one descriptor, listening or not, and no thread of its own;
 * every listening port is served by the one selector thread. A break stops the ports at once and
 * a resume reopens them on the same numbers, without a descriptor more; no socket that does not
 * share the number on purpose (SO_REUSEPORT, same user) can bind it meanwhile.
 */
@Tag("slow")
class PortDescriptorsTest {

    private static final int ROBOTS = 12;

    @Test
    void aPortCostsOneDescriptorListeningOrNotAndNoThread() throws Exception {
        try (TestHub hub = new TestHub(new NoopPropagationModel(), TestHub.config(true, 65536, 600, 1000, 30))) {
            warmUp(hub);
            long descriptorsBefore = Sockets.openDescriptors();
            int threadsBefore = Thread.activeCount();

            List<TestRobot> robots = new ArrayList<>();
            List<ServerSocket> accepting = new ArrayList<>();
            for (int i = 0; i < ROBOTS; i++) {
                TestRobot robot = hub.robot();
                accepting.add(robot.initAccepting("R" + i));
                robots.add(robot);
            }
            int[][] numbers = new int[ROBOTS][ROBOTS];
            for (int i = 0; i < ROBOTS; i++) {
                for (int j = 0; j < ROBOTS; j++) {
                    if (i != j) {
                        numbers[i][j] = robots.get(i).dns("R" + j, 0);
                    }
                }
            }
            int ports = ROBOTS * (ROBOTS - 1);
            // Each robot: its control socket and its accepting socket here, its control connection in the hub.
            long expected = descriptorsBefore + 3L * ROBOTS + ports;
            assertEquals(expected, Wait.settle("the descriptors of the mesh", Sockets::openDescriptors, n -> n == expected),
                    "one descriptor per listening port (" + ports + " ports, " + ROBOTS + " robots)");
            // A thread per control connection, and the warnings' summary thread: the 132 "allocated" lines
            // from one address are over the INFO limit (docs/reliability.md); none per port.
            assertTrue(Thread.activeCount() <= threadsBefore + ROBOTS + 1, "a thread per control connection, none per port: "
                    + threadsBefore + " threads before, " + Thread.activeCount() + " with " + ports + " ports listening");
            for (int j = 1; j < ROBOTS; j++) {
                assertEquals(1, Sockets.listeningSockets(numbers[j][0]), "one listening socket on R" + j + " -> R0");
            }

            // R0 out of range of every other robot: its ports stop at once, on one descriptor each.
            for (int j = 1; j < ROBOTS; j++) {
                hub.hub.robotLinks().breakConnectionsForPair("R0", "R" + j);
                int toR0 = numbers[j][0];
                int fromR0 = numbers[0][j];
                assertEquals(0, Sockets.listeningSockets(toR0), "stopped when the break returned");
                assertThrows(ConnectException.class, () -> robots.get(0).connect(toR0).close(), "refused once broken");
                assertThrows(ConnectException.class, () -> robots.get(0).connect(fromR0).close(), "refused once broken");
            }
            assertEquals(expected, Sockets.openDescriptors(), "a port that does not listen holds its number on one descriptor");
            assertNumbersTaken(numbers[1][0]);
            try (Socket other = robots.get(2).connect(numbers[2][1])) {
                Sockets.send(other, "x");
                try (Socket arrived = accepting.get(1).accept()) {
                    assertEquals("x", Sockets.readExactly(arrived.getInputStream(), 1), "the other ports listen on");
                }
            }

            for (int j = 1; j < ROBOTS; j++) {
                hub.hub.robotLinks().resumeConnectionsForPair("R0", "R" + j);
                assertEquals(1, Sockets.listeningSockets(numbers[j][0]), "listens again on the same number");
            }
            Wait.until("the link of the check ended", () -> Sockets.linkThreads() == 0);
            assertEquals(expected, Wait.settle("the descriptors after the resume", Sockets::openDescriptors, n -> n == expected));
            try (Socket again = robots.get(3).connect(numbers[3][0]); Socket arrived = accepting.get(0).accept()) {
                Sockets.send(again, "y");
                assertEquals("y", Sockets.readExactly(arrived.getInputStream(), 1), "a resumed port forwards");
            }
            assertNumbersTaken(numbers[3][0]);
            Sockets.closeAllNewestFirst(robots);
        }
    }

    /** A socket of any kind that does not set SO_REUSEPORT cannot bind a port's number, SO_REUSEADDR or not. */
    private static void assertNumbersTaken(int number) throws IOException {
        InetSocketAddress address = new InetSocketAddress("127.0.0.1", number);
        for (boolean reuseAddress : new boolean[] {false, true}) {
            try (SocketChannel socket = SocketChannel.open(); ServerSocketChannel server = ServerSocketChannel.open()) {
                for (NetworkChannel channel : new NetworkChannel[] {socket, server}) {
                    channel.setOption(StandardSocketOptions.SO_REUSEADDR, reuseAddress);
                    assertThrows(IOException.class, () -> channel.bind(address),
                            channel + " with SO_REUSEADDR " + reuseAddress + " bound WSS port " + number);
                }
            }
        }
    }

    /** The selector's threads started and the classes loaded, before the counts are taken. */
    private static void warmUp(TestHub hub) throws Exception {
        try (TestRobot a = hub.robot(); TestRobot b = hub.robot()) {
            a.initAccepting("warmA");
            ServerSocket bAccepts = b.initAccepting("warmB");
            try (Socket data = a.connect(a.dns("warmB", 0)); Socket arrived = bAccepts.accept()) {
                Sockets.send(data, "w");
                assertEquals("w", Sockets.readExactly(arrived.getInputStream(), 1));
            }
            b.dns("warmA", 0);
            hub.hub.robotLinks().breakConnectionsForPair("warmA", "warmB");
            hub.hub.robotLinks().resumeConnectionsForPair("warmA", "warmB");
        }
        Wait.until("the warm-up robots are gone", () -> hub.hub.snapshot().robots().isEmpty());
        hub.hub.robotLinks().kickOutRobot("warmA");
        hub.hub.robotLinks().kickOutRobot("warmB");
        Wait.until("the warm-up's link ended", () -> Sockets.linkThreads() == 0);
    }
}
