package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.hub.Sockets.listeningSockets;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.ConnectException;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.List;
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
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.WssEventListener;

/**
 * A pair broken and resumed 20 times a second while data flows both ways: each robot's writer
 * reconnects after every break and streams sequence numbers; every byte received must be the
 * next one of its connection's sequence, the WSS ports must listen after every resume, and once
 * it is over no thread nor descriptor is left behind. {@code -Dwss.soak=true} runs it for a minute.
 */
@Timeout(value = 5, unit = TimeUnit.MINUTES)
@Tag("slow")
class BreakResumeStormTest {

    private static final boolean SOAK = Boolean.getBoolean("wss.soak");
    /** Break, then resume, every 25 ms: 20 of each a second. */
    private static final long TOGGLE_MS = 25;
    private static final int TOGGLES = (SOAK ? 60 : 3) * 2 * 20;
    /** How long after a resume both writers must have connected again. */
    private static final long RECONNECT_NS = TimeUnit.SECONDS.toNanos(10);

    private ScriptedModel model;
    private TestHub server;
    private RobotLinkModel links;
    private final ExecutorService pool = Executors.newCachedThreadPool();
    private final ScheduledExecutorService storm = Executors.newSingleThreadScheduledExecutor();
    private final ConcurrentLinkedQueue<String> problems = new ConcurrentLinkedQueue<>();
    private final AtomicInteger established = new AtomicInteger();
    private volatile boolean stopping;

    @BeforeEach
    void start() throws Exception {
        model = new ScriptedModel();
        server = new TestHub(model, true, 65536);
        links = model.links();
        server.hub.addListener(new WssEventListener() {
            @Override
            public void connectionEstablished(String from, String to, int targetPort) {
                established.incrementAndGet();
            }
        });
    }

    @AfterEach
    void stop() throws Exception {
        stopping = true;
        storm.shutdownNow();
        server.close();
        pool.shutdownNow();
        assertTrue(pool.awaitTermination(10, TimeUnit.SECONDS));
    }

    /** One direction's traffic: what its writer did, what its receiver checked. */
    private static final class Flow {
        final AtomicInteger connections = new AtomicInteger();
        final AtomicLong received = new AtomicLong();
        final AtomicInteger streams = new AtomicInteger();
        /** Connects that failed otherwise than refused (a timeout, no local port free): tried again. */
        final ConcurrentLinkedQueue<String> failedConnects = new ConcurrentLinkedQueue<>();
    }

    @Test
    void breakingAndResumingTwentyTimesASecondLosesNoOrderAndLeavesNothingBehind() throws Exception {
        storm("break/resume", n -> check(links.breakConnectionsForPair("R1", "R2"), "break " + n + " changed something"),
                n -> check(links.resumeConnectionsForPair("R2", "R1"), "resume " + n + " changed something"));
    }

    /**
     * Issue 27: the same storm by an operator's FORCE Down and Up. Once a pair's FORCED DOWN is
     * said, no link of the pair sends a byte more: the events hold no DATA_SENT between a FORCED
     * DOWN and the next FORCED UP (there were 10 to 41 in 600 forced downs, 0 to 3 ms after it).
     * Nor a CON_ESTABLISHED (issue 36: 7 in 600 forced downs, 0 to 5 ms after it, of links
     * connecting to their target as the force came; a guard here, the rule's own tests are
     * {@code HubCoreTest} and {@code LinkClockTest}, which do not depend on timing).
     */
    @Test
    void forcingDownAndUpTwentyTimesASecondSendsNothingAfterAForcedDown() throws Exception {
        AtomicInteger sentWhileDown = new AtomicInteger();
        AtomicInteger establishedWhileDown = new AtomicInteger();
        AtomicInteger forcedDowns = new AtomicInteger();
        server.hub.addListener(new WssEventListener() {
            private volatile boolean down;

            @Override
            public void pairForced(String first, String second, boolean up) {
                down = !up;
                if (!up) {
                    forcedDowns.incrementAndGet();
                }
            }

            @Override
            public void dataSent(String from, String to, int bytes) {
                if (down) {
                    sentWhileDown.incrementAndGet();
                }
            }

            @Override
            public void connectionEstablished(String from, String to, int targetPort) {
                if (down) {
                    establishedWhileDown.incrementAndGet();
                }
            }
        });
        storm("FORCE Down/Up", n -> server.hub.force("R1", "R2", Force.DOWN), n -> server.hub.force("R2", "R1", Force.UP));
        System.out.printf("FORCE storm: %d forced downs, %d DATA_SENT after a FORCED DOWN%n", forcedDowns.get(), sentWhileDown.get());
        assertEquals(TOGGLES / 2, forcedDowns.get());
        assertEquals(0, sentWhileDown.get(), "DATA_SENT after a FORCED DOWN, before the FORCED UP");
        assertEquals(0, establishedWhileDown.get(), "CON_ESTABLISHED after a FORCED DOWN, before the FORCED UP");
    }

    /** What the storm does at its n-th break or resume. */
    private interface Toggle {
        void run(int n);
    }

    private void storm(String what, Toggle breakIt, Toggle resumeIt) throws Exception {
        try (TestRobot r1 = server.robotAt("127.0.0.1"); TestRobot r2 = server.robotAt("127.0.0.2")) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            ServerSocket r2Accepts = r2.initAccepting("R2");
            int toR1 = r2.dns("R1", 0);
            int toR2 = r1.dns("R2", 0);
            Flow r2ToR1 = new Flow();
            Flow r1ToR2 = new Flow();
            List<Future<?>> tasks = new ArrayList<>();
            tasks.add(pool.submit(() -> receive(r1Accepts, r2ToR1)));
            tasks.add(pool.submit(() -> receive(r2Accepts, r1ToR2)));

            // A connection each way first, so that what the JVM opens once is open before counting.
            warmUp(r2, toR1, r2ToR1);
            warmUp(r1, toR2, r1ToR2);
            Wait.until("the warm-up's links ended", () -> Sockets.linkThreads() == 0);
            long threadsBefore = serverThreads();
            long descriptorsBefore = Wait.settle("descriptors settle", Sockets::openDescriptors, n -> true);
            tasks.add(pool.submit(() -> write(r2, toR1, r2ToR1)));
            tasks.add(pool.submit(() -> write(r1, toR2, r1ToR2)));
            Wait.until("bytes flow both ways", () -> r2ToR1.received.get() > 0 && r1ToR2.received.get() > 0);

            ConcurrentLinkedQueue<Long> replyMs = new ConcurrentLinkedQueue<>();
            ScheduledExecutorService asking = Executors.newSingleThreadScheduledExecutor();
            asking.scheduleAtFixedRate(() -> {
                long start = System.nanoTime();
                try {
                    String reply = r1.ask("GETSS {Robot R2}");
                    replyMs.add(TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start));
                    check(reply.equals("SS {Robot R2} {Strength 0}"), "GETSS during the storm: " + reply);
                } catch (IOException e) {
                    problems.add("GETSS during the storm: " + e);
                }
            }, 0, 100, TimeUnit.MILLISECONDS);
            CountDownLatch stormOver = new CountDownLatch(1);
            AtomicInteger toggles = new AtomicInteger();
            Reconnected reconnected = new Reconnected(r2ToR1, r1ToR2);
            long stormStart = System.nanoTime();
            storm.scheduleAtFixedRate(() -> {
                int n = toggles.get();
                if (n % 2 == 0 && n > 0 && !reconnected.sinceResume(n / 2 - 1)) {
                    return; // the next break (or the end) waits for both writers to connect again
                }
                toggles.incrementAndGet();
                if (n >= TOGGLES) {
                    stormOver.countDown();
                    return;
                }
                if (n % 2 == 0) {
                    breakIt.run(n / 2);
                } else {
                    reconnected.resuming();
                    resumeIt.run(n / 2);
                    check(listens(r2, toR1), "R2 -> R1 listens after resume " + n / 2);
                    check(listens(r1, toR2), "R1 -> R2 listens after resume " + n / 2);
                }
            }, TOGGLE_MS, TOGGLE_MS, TimeUnit.MILLISECONDS);
            assertTrue(stormOver.await(TOGGLES * TOGGLE_MS * 20, TimeUnit.MILLISECONDS), "the storm ended");
            long stormMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - stormStart);
            storm.shutdown();
            asking.shutdown();
            assertTrue(asking.awaitTermination(10, TimeUnit.SECONDS));

            long before1 = r2ToR1.received.get();
            long before2 = r1ToR2.received.get();
            Wait.until("bytes flow both ways after the storm",
                    () -> r2ToR1.received.get() > before1 && r1ToR2.received.get() > before2);
            stopping = true;
            for (Future<?> task : tasks) {
                task.get(10, TimeUnit.SECONDS);
            }
            long[] ms = replyMs.stream().mapToLong(Long::longValue).sorted().toArray();
            System.out.printf("%s storm: %d breaks and resumes in %d ms; R2 -> R1 %d connections, %d streams,"
                    + " %d bytes; R1 -> R2 %d connections, %d streams, %d bytes; %d links established (probes included);"
                    + " connects failed otherwise than refused %s %s; %d GETSS meanwhile, ms p50 %d, p99 %d, max %d%n",
                    what, TOGGLES / 2, stormMs,
                    r2ToR1.connections.get(), r2ToR1.streams.get(), r2ToR1.received.get(),
                    r1ToR2.connections.get(), r1ToR2.streams.get(), r1ToR2.received.get(), established.get(),
                    r2ToR1.failedConnects, r1ToR2.failedConnects, ms.length, ms[ms.length / 2], ms[ms.length * 99 / 100],
                    ms[ms.length - 1]);
            assertEquals(List.of(), List.copyOf(problems));
            // Every GETSS was answered, right, within the control connection's read timeout (a hub that held it up
            // behind the storm's socket work is a problem above); how fast is the machine's figure, printed, not asserted:
            // the 1 s bound this had was missed at load 33 by the code before the hub split as after it.
            // Each writer's first connection, and one after each resume (or a problem above said which resume it missed).
            assertTrue(r2ToR1.connections.get() > TOGGLES / 2 && r1ToR2.connections.get() > TOGGLES / 2,
                    "the writers reconnected after every break");

            Wait.until("every link thread ended", () -> Sockets.linkThreads() == 0);
            long threadsAfter = Wait.settle("the server's threads return to their level", BreakResumeStormTest::serverThreads,
                    n -> n <= threadsBefore);
            assertTrue(threadsAfter <= threadsBefore, "server threads before " + threadsBefore + ", after " + threadsAfter);
            assertEquals(1, listeningSockets(toR1), "one listening socket for R2 -> R1");
            assertEquals(1, listeningSockets(toR2), "one listening socket for R1 -> R2");
            long descriptorsAfter = Wait.settle("descriptors return to their level", Sockets::openDescriptors,
                    n -> n <= descriptorsBefore);
            assertTrue(descriptorsAfter <= descriptorsBefore + 2,
                    "open descriptors before " + descriptorsBefore + ", after " + descriptorsAfter);
        }
    }

    /**
     * Whether both writers connected again after the last resume: the break it ended must have
     * ended their connections, and the resume let them in. The next break waits for it, so that
     * every listening window is used whatever the machine's load (on a loaded machine the storm's
     * late turns came back to back and a writer woke too late for a window; the writers' count
     * then said nothing of the hub). A writer that does not connect within {@link #RECONNECT_NS}
     * of a resume is a problem, and the storm goes on.
     */
    private final class Reconnected {
        private final Flow[] flows;
        private final int[] before;
        private long resumedAt;

        Reconnected(Flow... flows) {
            this.flows = flows;
            this.before = new int[flows.length];
        }

        /** Just before a resume: the break before it ended every connection, so the counts now are the old ones. */
        void resuming() {
            for (int i = 0; i < flows.length; i++) {
                before[i] = flows[i].connections.get();
            }
            resumedAt = System.nanoTime();
        }

        boolean sinceResume(int resume) {
            boolean all = true;
            for (int i = 0; i < flows.length; i++) {
                all &= flows[i].connections.get() > before[i];
            }
            if (!all && System.nanoTime() - resumedAt > RECONNECT_NS) {
                problems.add("a writer did not connect again within 10 s of resume " + resume);
                return true;
            }
            return all;
        }
    }

    /** One stream through the port, read whole at the other end before this returns. */
    private static void warmUp(TestRobot from, int port, Flow flow) throws IOException {
        try (Socket socket = from.connect(port)) {
            byte[] block = new byte[1024];
            Sockets.sequence(block, 0);
            socket.getOutputStream().write(block);
        }
        Wait.until("the warm-up stream arrived", () -> flow.received.get() >= 1024);
        flow.received.set(0);
    }

    private void check(boolean ok, String what) {
        if (!ok) {
            problems.add(what);
        }
    }

    /** Whether a connect to the WSS port succeeds now (it is accepted and forwarded; closed at once). */
    private boolean listens(TestRobot from, int port) {
        try (Socket probe = from.connect(port)) {
            return true;
        } catch (IOException e) {
            problems.add("a connect to WSS port " + port + " after a resume: " + e);
            return false;
        }
    }

    /** Connects again and again, streaming the sequence on each connection until it breaks. */
    private Void write(TestRobot from, int port, Flow flow) throws IOException {
        byte[] block = new byte[1024];
        while (!stopping) {
            Socket socket;
            try {
                socket = from.connect(port);
            } catch (ConnectException refused) {
                LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(1)); // broken: try again in a moment
                continue;
            } catch (IOException e) {
                flow.failedConnects.add(e.toString());
                LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(1));
                continue;
            }
            flow.connections.incrementAndGet();
            try (socket) {
                OutputStream out = socket.getOutputStream();
                for (long position = 0; !stopping; position += block.length) {
                    Sockets.sequence(block, position);
                    out.write(block);
                }
            } catch (SocketException broken) {
                // the break closed this connection: connect again
            } catch (IOException e) {
                problems.add("writing a stream: " + e);
            }
        }
        return null;
    }

    /** Accepts until the test stops; each connection is read on a thread of its own and checked byte by byte. */
    private Void receive(ServerSocket accepting, Flow flow) throws IOException {
        accepting.setSoTimeout(50);
        while (!stopping) {
            Socket socket;
            try {
                socket = accepting.accept();
            } catch (SocketTimeoutException idle) {
                continue;
            }
            flow.streams.incrementAndGet();
            pool.submit(() -> readChecked(socket, flow));
        }
        return null;
    }

    private Void readChecked(Socket socket, Flow flow) {
        byte[] block = new byte[8192];
        byte[] expected = new byte[8192];
        long position = 0;
        try (socket; InputStream in = socket.getInputStream()) {
            socket.setSoTimeout((int) TimeUnit.SECONDS.toMillis(30));
            int read;
            while ((read = in.read(block)) >= 0) {
                Sockets.sequence(expected, position);
                for (int i = 0; i < read; i++) {
                    if (block[i] != expected[i]) {
                        problems.add("byte " + (position + i) + " of a stream: " + block[i] + " where " + expected[i] + " was sent");
                        return null;
                    }
                }
                position += read;
                flow.received.addAndGet(read);
            }
        } catch (SocketException reset) {
            // the break reset it: what came before was checked
        } catch (IOException e) {
            problems.add("reading a stream: " + e);
        }
        return null;
    }


    /** The server's own threads: links, the WSS ports' selector and hand-over, control connections. */
    private static long serverThreads() {
        return Thread.getAllStackTraces().keySet().stream().map(Thread::getName)
                .filter(n -> n.startsWith("link ") || n.startsWith("wss-port-accept") || n.startsWith("wss-port-handover") || n.startsWith("control ")).count();
    }
}
