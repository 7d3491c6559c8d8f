package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * 200 robots on one hub, each sending to three others through WSS ports while every robot asks
 * GETSS on its control connection every 100 ms. Every forwarded byte is checked (a SHA-256 of
 * each stream at both ends) and every GETSS must be answered within 1 s; the test prints the
 * reply times. {@code -Dwss.soak=true} (the Maven profile {@code soak}) makes it longer:
 * docs/reliability.md.
 */
@Timeout(value = 10, unit = TimeUnit.MINUTES)
@Tag("slow")
class LoadTest {

    private static final boolean SOAK = Boolean.getBoolean("wss.soak");
    private static final int ROBOTS = 200;
    /** Robot i sends to robots i + 1, i + 7 and i + 31: 600 streams between 600 different pairs. */
    private static final int[] PEERS = {1, 7, 31};
    /** Each stream's payload, after its 8-byte header. */
    private static final int BYTES = SOAK ? 1024 * 1024 : 128 * 1024;
    /** How many times every robot opens its streams again, one round after the other. */
    private static final int ROUNDS = SOAK ? 10 : 1;
    private static final long GETSS_EVERY_MS = 100;
    /** The issue's bound on a GETSS reply. */
    private static final long REPLY_WITHIN_MS = 1000;
    /** GETSS replies every robot gets at the least, however fast the streams are done. */
    private static final int MIN_GETSS_PER_ROBOT = 20;

    /** One stream as the receiving end saw it. */
    private record Received(long bytes, String digest) {
    }

    private final List<AutoCloseable> toClose = new ArrayList<>();
    private final ExecutorService pool = Executors.newCachedThreadPool();
    private final ScheduledExecutorService asking = Executors.newScheduledThreadPool(8);

    @AfterEach
    void stop() throws Exception {
        asking.shutdownNow();
        pool.shutdownNow();
        for (AutoCloseable closeable : toClose) {
            closeable.close();
        }
        assertTrue(asking.awaitTermination(10, TimeUnit.SECONDS));
        assertTrue(pool.awaitTermination(10, TimeUnit.SECONDS));
    }

    @Test
    void twoHundredRobotsStreamingLoseNoByteAndEveryGetssIsAnsweredWithinOneSecond() throws Exception {
        TestHub server = new TestHub();
        toClose.add(server);
        List<TestRobot> robots = new ArrayList<>();
        List<ServerSocket> accepts = new ArrayList<>();
        for (int i = 0; i < ROBOTS; i++) {
            TestRobot robot = server.robot();
            toClose.add(0, robot);
            robots.add(robot);
            accepts.add(robot.initAccepting(name(i)));
        }
        int[][] ports = new int[ROBOTS][PEERS.length];
        for (int i = 0; i < ROBOTS; i++) {
            for (int k = 0; k < PEERS.length; k++) {
                ports[i][k] = robots.get(i).dns(name((i + PEERS[k]) % ROBOTS), 0);
            }
        }

        long expected = (long) ROBOTS * PEERS.length * ROUNDS;
        Map<Long, Received> received = new ConcurrentHashMap<>();
        CountDownLatch allReceived = new CountDownLatch((int) expected);
        for (ServerSocket accepting : accepts) {
            pool.submit(() -> receiveAll(accepting, PEERS.length * ROUNDS, received, allReceived));
        }
        ConcurrentLinkedQueue<Long> replyMs = new ConcurrentLinkedQueue<>();
        ConcurrentLinkedQueue<String> wrongReplies = new ConcurrentLinkedQueue<>();
        CountDownLatch enoughAsked = new CountDownLatch(ROBOTS);
        for (int i = 0; i < ROBOTS; i++) {
            TestRobot robot = robots.get(i);
            String other = name((i + 1) % ROBOTS);
            AtomicInteger asked = new AtomicInteger();
            asking.scheduleAtFixedRate(() -> {
                long start = System.nanoTime();
                try {
                    String reply = robot.ask("GETSS {Robot " + other + "}");
                    replyMs.add(TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start));
                    if (!reply.equals("SS {Robot " + other + "} {Strength 0}")) {
                        wrongReplies.add(reply);
                    }
                } catch (IOException e) {
                    wrongReplies.add(e.toString());
                }
                if (asked.incrementAndGet() == MIN_GETSS_PER_ROBOT) {
                    enoughAsked.countDown();
                }
            }, i % GETSS_EVERY_MS, GETSS_EVERY_MS, TimeUnit.MILLISECONDS);
        }

        AtomicLong stallMs = new AtomicLong();
        pool.submit(() -> watchStalls(stallMs));
        long started = System.nanoTime();
        Map<Long, String> sent = new ConcurrentHashMap<>();
        ExecutorService senders = Executors.newFixedThreadPool(32);
        try {
            for (int round = 0; round < ROUNDS; round++) {
                List<Future<?>> streams = new ArrayList<>();
                for (int i = 0; i < ROBOTS; i++) {
                    for (int k = 0; k < PEERS.length; k++) {
                        TestRobot robot = robots.get(i);
                        int port = ports[i][k];
                        long id = ((long) round * ROBOTS + i) * PEERS.length + k;
                        streams.add(senders.submit(() -> {
                            sent.put(id, send(robot, port, id));
                            return null;
                        }));
                    }
                }
                for (Future<?> stream : streams) {
                    stream.get(5, TimeUnit.MINUTES);
                }
            }
        } finally {
            senders.shutdownNow();
        }
        allReceived.await(2, TimeUnit.MINUTES);
        long streamsMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
        assertTrue(enoughAsked.await(2, TimeUnit.MINUTES), "every robot got " + MIN_GETSS_PER_ROBOT + " GETSS replies");
        asking.shutdown();
        assertTrue(asking.awaitTermination(30, TimeUnit.SECONDS));
        long askedMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);

        assertEquals(expected, received.size(), "streams received whole (end of stream seen)");
        for (Map.Entry<Long, String> stream : sent.entrySet()) {
            Received at = received.get(stream.getKey());
            assertEquals((long) BYTES, at.bytes(), "bytes of stream " + stream.getKey());
            assertEquals(stream.getValue(), at.digest(), "SHA-256 of stream " + stream.getKey());
        }
        long[] ms = replyMs.stream().mapToLong(Long::longValue).sorted().toArray();
        System.out.printf("load: %d robots, %d streams of %d KiB (%d MiB) in %d ms; %d GETSS in %d ms (%.0f a second),"
                + " reply ms p50 %d, p99 %d, max %d; the longest a test thread waited to wake up: %d ms%n", ROBOTS, expected,
                BYTES / 1024, expected * BYTES >> 20, streamsMs, ms.length, askedMs, ms.length * 1000.0 / askedMs,
                percentile(ms, 50), percentile(ms, 99), ms[ms.length - 1], stallMs.get());
        assertEquals(List.of(), List.copyOf(wrongReplies), "every GETSS answered rightly");
        long late = Arrays.stream(ms).filter(m -> m >= REPLY_WITHIN_MS).count();
        assertEquals(0, late, late + " of " + ms.length + " GETSS replies took " + REPLY_WITHIN_MS + " ms or more");

        for (AutoCloseable closeable : toClose) {
            closeable.close();
        }
        toClose.clear();
        Wait.until("every link thread ended", () -> Sockets.linkThreads() == 0);
    }

    /**
     * How late a thread that sleeps 10 ms at a time wakes up, at worst, until the test ends: what
     * the machine (other processes, the JVM's pauses) adds to every time measured here.
     */
    private static Void watchStalls(AtomicLong worstMs) {
        while (!Thread.currentThread().isInterrupted()) {
            long start = System.nanoTime();
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(10));
            long lateMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start) - 10;
            worstMs.accumulateAndGet(lateMs, Math::max);
        }
        return null;
    }

    private static String name(int i) {
        return "R" + i;
    }

    /** One stream from the robot through the WSS port: its id, then the payload; returns the SHA-256 of all of it. */
    private static String send(TestRobot robot, int wssPort, long id) throws IOException {
        MessageDigest digest = sha256();
        Random random = new Random(id);
        byte[] block = new byte[64 * 1024];
        try (Socket socket = robot.connect(wssPort)) {
            socket.setSoTimeout((int) TimeUnit.MINUTES.toMillis(2));
            OutputStream out = socket.getOutputStream();
            byte[] header = new byte[8];
            for (int b = 0; b < 8; b++) {
                header[b] = (byte) (id >>> (56 - 8 * b));
            }
            out.write(header);
            digest.update(header);
            for (int left = BYTES; left > 0; left -= block.length) {
                random.nextBytes(block);
                int length = Math.min(left, block.length);
                out.write(block, 0, length);
                digest.update(block, 0, length);
            }
            socket.shutdownOutput();
            // The end of stream comes back once the target has read everything and closed.
            if (socket.getInputStream().read() != -1) {
                throw new IOException("stream " + id + ": the target sent something");
            }
        }
        return HexFormat.of().formatHex(digest.digest());
    }

    /** Accepts {@code count} streams and reads each to its end on a thread of its own. */
    private Void receiveAll(ServerSocket accepting, int count, Map<Long, Received> received, CountDownLatch allReceived)
            throws IOException {
        accepting.setSoTimeout(0);
        for (int n = 0; n < count; n++) {
            Socket socket = accepting.accept();
            pool.submit(() -> {
                try (socket; InputStream in = socket.getInputStream()) {
                    socket.setSoTimeout((int) TimeUnit.MINUTES.toMillis(2));
                    MessageDigest digest = sha256();
                    byte[] header = in.readNBytes(8);
                    digest.update(header);
                    long id = 0;
                    for (byte b : header) {
                        id = id << 8 | (b & 0xff);
                    }
                    byte[] block = new byte[64 * 1024];
                    long bytes = 0;
                    int read;
                    while ((read = in.read(block)) >= 0) {
                        digest.update(block, 0, read);
                        bytes += read;
                    }
                    if (received.putIfAbsent(id, new Received(bytes, HexFormat.of().formatHex(digest.digest()))) != null) {
                        fail("stream " + id + " arrived twice");
                    }
                    allReceived.countDown();
                }
                return null;
            });
        }
        return null;
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new AssertionError(e);
        }
    }

    private static long percentile(long[] sorted, int percent) {
        return sorted[Math.min(sorted.length - 1, sorted.length * percent / 100)];
    }
}
