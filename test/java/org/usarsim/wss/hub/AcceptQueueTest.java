package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A whole team starting at once: 1,000 robots connect to the control port in one burst (every
 * SYN sent before the first connection is accepted) and send INIT. With an accept queue of 128
 * some SYNs found it full, were dropped, and waited a whole second for their retransmission;
 * with the queue the control port has now, every connect completes before a retransmission could
 * even happen, and every INIT is answered.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class AcceptQueueTest {

    private static final int ROBOTS = 1000;
    /** Linux retransmits an unanswered SYN after 1 s: a connect that took this long lost its first SYN. */
    private static final long SYN_RETRANSMIT_MS = 1000;

    /** One robot's control connection in the burst, with when each step completed. */
    private static final class Client {
        final SocketChannel channel;
        final String name;
        long started;
        final ByteBuffer reply = ByteBuffer.allocate(256);
        long connectedNs = -1;
        long answeredNs = -1;

        Client(int i) throws IOException {
            name = "R" + i;
            channel = SocketChannel.open();
            channel.configureBlocking(false);
        }

        String replyText() {
            return new String(reply.array(), 0, reply.position(), StandardCharsets.UTF_8);
        }
    }

    @Test
    void aThousandRobotsConnectingAtOnceAreAllAnsweredWithoutASynRetransmit() throws Exception {
        List<Client> clients = new ArrayList<>();
        long overflowsBefore = listenOverflows();
        try (TestHub server = new TestHub(); Selector selector = Selector.open()) {
            InetSocketAddress control = new InetSocketAddress("127.0.0.1", server.port());
            for (int i = 0; i < ROBOTS; i++) {
                Client client = new Client(i);
                clients.add(client);
                client.started = System.nanoTime();
                if (client.channel.connect(control)) {
                    connected(client, selector);
                } else {
                    client.channel.register(selector, SelectionKey.OP_CONNECT, client);
                }
            }
            int answered = 0;
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (answered < ROBOTS) {
                long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
                if (left <= 0) {
                    fail(answered + " of " + ROBOTS + " INITs answered within 30 s");
                }
                selector.select(left);
                for (SelectionKey key : selector.selectedKeys()) {
                    Client client = (Client) key.attachment();
                    if (key.isConnectable()) {
                        client.channel.finishConnect();
                        connected(client, selector);
                    } else if (key.isReadable()) {
                        if (client.channel.read(client.reply) < 0) {
                            fail(client.name + ": control connection closed after '" + client.replyText() + "'");
                        }
                        if (client.replyText().endsWith("\r\n")) {
                            client.answeredNs = System.nanoTime();
                            key.cancel();
                            answered++;
                        }
                    }
                }
                selector.selectedKeys().clear();
            }
            long[] connectMs = clients.stream().mapToLong(c -> TimeUnit.NANOSECONDS.toMillis(c.connectedNs - c.started)).sorted().toArray();
            long[] initMs = clients.stream().mapToLong(c -> TimeUnit.NANOSECONDS.toMillis(c.answeredNs - c.started)).sorted().toArray();
            System.out.println("accept queue: " + ROBOTS + " robots at once; connect ms " + summary(connectMs)
                    + "; INIT answered ms (from connect start) " + summary(initMs)
                    + "; the machine's TcpExt ListenOverflows meanwhile: " + (listenOverflows() - overflowsBefore));
            for (Client client : clients) {
                assertEquals("INITREPLY {Status OK}\r\n", client.replyText(), client.name);
            }
            assertEquals(ROBOTS, server.hub.getListOfRegisteredRobots().size());
            long slow = Arrays.stream(connectMs).filter(ms -> ms >= SYN_RETRANSMIT_MS).count();
            assertTrue(slow == 0, slow + " of " + ROBOTS + " connects took a SYN retransmit (" + SYN_RETRANSMIT_MS
                    + " ms or more): connect ms " + summary(connectMs) + "; the OS caps the queue at net.core.somaxconn, "
                    + Files.readString(Path.of("/proc/sys/net/core/somaxconn")).strip() + " here");
        } finally {
            for (Client client : clients) {
                client.channel.close();
            }
        }
    }

    private static void connected(Client client, Selector selector) throws IOException {
        client.connectedNs = System.nanoTime();
        ByteBuffer init = ByteBuffer.wrap(("INIT {Robot " + client.name + "}\r\n").getBytes(StandardCharsets.UTF_8));
        while (init.hasRemaining()) {
            client.channel.write(init);
        }
        client.channel.register(selector, SelectionKey.OP_READ, client);
    }

    /**
     * How many times a listening socket on this machine found its accept queue full (all
     * processes: for the report only, another program may have overflowed its own).
     */
    private static long listenOverflows() throws IOException {
        List<String> lines = Files.readAllLines(Path.of("/proc/net/netstat"));
        for (int i = 0; i + 1 < lines.size(); i += 2) {
            List<String> names = List.of(lines.get(i).split(" "));
            String[] values = lines.get(i + 1).split(" ");
            int at = names.indexOf("ListenOverflows");
            if (names.get(0).equals("TcpExt:") && at > 0) {
                return Long.parseLong(values[at]);
            }
        }
        return -1;
    }

    private static String summary(long[] sortedMs) {
        return "p50 " + sortedMs[sortedMs.length / 2] + ", p99 " + sortedMs[sortedMs.length * 99 / 100]
                + ", max " + sortedMs[sortedMs.length - 1];
    }
}
