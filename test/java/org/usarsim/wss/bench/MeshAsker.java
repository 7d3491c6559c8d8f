package org.usarsim.wss.bench;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * Every robot asks DNS for every other, all robots at once, each over its own control connection
 * and one question at a time, as a robot does: it writes its next DNS once it has read the reply
 * to the last, and checks that reply. One thread drives every connection (a Selector), so that
 * the robots' side takes little of the cores it shares with the server: a thread per robot reading
 * its replies a byte at a time took 2 to 2.8 s of CPU for 9,900 DNS, about as much as the server.
 */
final class MeshAsker {

    /** How long the server may leave every robot without a reply before the mesh is given up. */
    private static final int REPLY_TIMEOUT_MS = 10_000;

    /**
     * ports[i][j]: the port from robot i to robot j (0: refused); how many were refused, the first
     * refusal; the seconds for all, and when each tenth of the replies had come (the JIT's part shows).
     */
    record Answers(int[][] ports, int refused, String firstRefusal, double seconds, double[] tenths) {
    }

    private MeshAsker() {
    }

    /** The robots' names are {@code prefix} and their index in {@code clients}. */
    static Answers askAll(List<ControlClient> clients, String prefix) throws IOException {
        int robots = clients.size();
        int[][] ports = new int[robots][robots];
        Robot[] asking = new Robot[robots];
        double[] tenths = new double[10];
        long start;
        try (Selector selector = Selector.open()) {
            for (int i = 0; i < robots; i++) {
                SocketChannel channel = clients.get(i).channel();
                channel.configureBlocking(false);
                asking[i] = new Robot(i, robots, prefix, channel, ports[i]);
                channel.register(selector, SelectionKey.OP_READ, asking[i]);
            }
            start = System.nanoTime();
            int asked = robots * (robots - 1);
            int[] replies = new int[1];
            int left = 0;
            for (Robot robot : asking) {
                if (robot.askNext()) {
                    left++;
                }
            }
            while (left > 0) {
                int[] done = new int[1];
                IOException[] failed = new IOException[1];
                int ready = selector.select(key -> {
                    try {
                        Robot robot = (Robot) key.attachment();
                        int before = robot.replies;
                        if (!robot.readReplies()) {
                            done[0]++;
                        }
                        for (int reply = replies[0] + 1; reply <= replies[0] + robot.replies - before; reply++) {
                            if (reply % Math.max(1, asked / 10) == 0 && reply / Math.max(1, asked / 10) <= 10) {
                                tenths[reply / Math.max(1, asked / 10) - 1] = (System.nanoTime() - start) / 1e9;
                            }
                        }
                        replies[0] += robot.replies - before;
                    } catch (IOException e) {
                        failed[0] = e;
                    }
                }, REPLY_TIMEOUT_MS);
                if (failed[0] != null) {
                    throw failed[0];
                }
                if (ready == 0) {
                    throw new IOException("no reply in " + REPLY_TIMEOUT_MS + " ms");
                }
                left -= done[0];
            }
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        for (ControlClient client : clients) {
            client.channel().configureBlocking(true); // the selector is closed: the channels are free of it
        }
        int refused = 0;
        String first = null;
        for (Robot robot : asking) {
            refused += robot.refused;
            if (first == null) {
                first = robot.firstRefusal;
            }
        }
        return new Answers(ports, refused, first, seconds, tenths);
    }

    /** One robot's questions: R{from} asks DNS of each other robot in turn. */
    private static final class Robot {
        private final int from;
        private final int robots;
        private final String prefix;
        private final SocketChannel channel;
        private final int[] ports;
        private final ByteBuffer in = ByteBuffer.allocate(1024);
        /** The robot asked now, and the reply expected up to its number. */
        private int to = -1;
        private String expected;
        private int refused;
        private String firstRefusal;
        private int replies;

        Robot(int from, int robots, String prefix, SocketChannel channel, int[] ports) {
            this.from = from;
            this.robots = robots;
            this.prefix = prefix;
            this.channel = channel;
            this.ports = ports;
        }

        /** Writes the next DNS. @return false when every other robot has been asked */
        boolean askNext() throws IOException {
            to++;
            if (to == from) {
                to++;
            }
            if (to >= robots) {
                return false;
            }
            String name = prefix + to;
            expected = "DNSREPLY {Robot " + name + "} {Port ";
            ByteBuffer out = ByteBuffer.wrap(("DNS {Robot " + name + "}\r\n").getBytes(StandardCharsets.US_ASCII));
            channel.write(out);
            if (out.hasRemaining()) {
                // One short line to a connection with nothing unread: the send buffer is empty.
                throw new IOException("R" + from + ": the DNS did not fit the send buffer");
            }
            return true;
        }

        /** Reads what arrived; for a whole reply, notes it and asks the next. @return false when done */
        boolean readReplies() throws IOException {
            if (channel.read(in) < 0) {
                throw new IOException(prefix + from + ": control connection closed");
            }
            in.flip();
            boolean asking = true;
            int lineStart = in.position();
            for (int i = lineStart; i < in.limit(); i++) {
                if (in.get(i) == '\n') {
                    String line = new String(in.array(), lineStart, i - lineStart, StandardCharsets.US_ASCII).strip();
                    lineStart = i + 1;
                    answered(line);
                    replies++;
                    asking = askNext();
                }
            }
            in.position(lineStart);
            in.compact();
            return asking;
        }

        private void answered(String line) {
            if (line.startsWith(expected) && line.endsWith("}")) {
                try {
                    ports[to] = Integer.parseInt(line.substring(expected.length(), line.length() - 1));
                    return;
                } catch (NumberFormatException e) {
                    // refused below
                }
            }
            if (refused++ == 0) {
                firstRefusal = "DNS " + prefix + to + " from " + prefix + from + ": " + line;
            }
        }
    }
}
