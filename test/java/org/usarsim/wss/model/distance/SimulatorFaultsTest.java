package org.usarsim.wss.model.distance;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.Sockets;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.simulator.DataConnection;
import org.usarsim.wss.model.simulator.FakeSimulator;
import org.usarsim.wss.model.simulator.ModelRig;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.protocol.Replies;

/**
 * The simulator dies, comes back, hangs (takes GETPOS and never answers), comes back, answers
 * garbage and comes back, one after the other, while a robot streams data to another and asks
 * GETSS and DNS every 100 ms: the stream flows and the replies come, within 1 s, during every
 * fault, and the log says each fault and each return once.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class SimulatorFaultsTest {

    private static final long ASK_EVERY_MS = 100;
    private static final long REPLY_WITHIN_MS = 1000;
    private static final int BLOCK = 1024;

    private ModelRig rig;
    private final ScheduledExecutorService traffic = Executors.newScheduledThreadPool(2);
    private final ExecutorService reader = Executors.newSingleThreadExecutor();
    private final ConcurrentLinkedQueue<String> problems = new ConcurrentLinkedQueue<>();
    private final ConcurrentLinkedQueue<Long> replyMs = new ConcurrentLinkedQueue<>();
    private final AtomicInteger replies = new AtomicInteger();
    private final AtomicLong received = new AtomicLong();

    @AfterEach
    void stop() throws Exception {
        traffic.shutdownNow();
        reader.shutdownNow();
        if (rig != null) {
            rig.close();
        }
        assertTrue(traffic.awaitTermination(10, TimeUnit.SECONDS));
    }

    @Test
    void robotsAreServedThroughoutASimulatorThatDiesHangsAndAnswersGarbage() throws Exception {
        rig = new ModelRig(new DistanceOnlyPropagationModel(), Map.of());
        TestRobot a = rig.robot("A", 0, 0, 0);
        rig.robot("B", 10, 0, 0);
        rig.polls(1);
        int port = a.dns("B", 0);
        DataConnection stream = DataConnection.open(a, port, rig.accepts("B"));
        String strength = a.ask("GETSS {Robot B}");
        assertEquals(Replies.signal("B", new PathLoss(-49.67, 1, 2, -93).strength(10)), strength);

        Future<Void> checked = reader.submit(() -> readInOrder(stream.target().getInputStream()));
        long[] written = {0};
        OutputStream out = stream.source().getOutputStream();
        traffic.scheduleAtFixedRate(() -> {
            byte[] block = new byte[BLOCK];
            Sockets.sequence(block, written[0]);
            try {
                out.write(block);
                written[0] += BLOCK;
            } catch (IOException e) {
                problems.add("writing the stream: " + e);
            }
        }, 0, 2, TimeUnit.MILLISECONDS);
        traffic.scheduleAtFixedRate(() -> {
            ask(a, "GETSS {Robot B}", strength);
            ask(a, "DNS {Robot B}", Replies.dns("B", port));
        }, 0, ASK_EVERY_MS, TimeUnit.MILLISECONDS);
        servedFor("before any fault");

        rig.sim.stopListening();
        fault(1, "the simulator died");
        rig.sim.listenAgain();
        back(1, "the simulator came back");

        rig.sim.mode(FakeSimulator.Mode.SILENT);
        fault(2, "the simulator hangs");
        assertEquals(1, rig.logLines(Level.WARNING, "no answer to GETPOS within 300 ms"), rig.log.toString());
        rig.sim.mode(FakeSimulator.Mode.ANSWER);
        back(2, "the simulator answers again");

        rig.sim.mode(FakeSimulator.Mode.GARBAGE);
        fault(3, "the simulator answers garbage");
        assertEquals(1, rig.logLines(Level.WARNING, "unexpected reply: this is not a reply"), rig.log.toString());
        rig.sim.mode(FakeSimulator.Mode.ANSWER);
        back(3, "the simulator answers sense again");

        traffic.shutdown();
        assertTrue(traffic.awaitTermination(10, TimeUnit.SECONDS));
        stream.source().shutdownOutput();
        checked.get(10, TimeUnit.SECONDS);
        stream.close();
        long[] ms = replyMs.stream().mapToLong(Long::longValue).sorted().toArray();
        System.out.printf("simulator faults: %d bytes streamed in order, %d GETSS and DNS replies, ms p50 %d, p99 %d, max %d%n",
                received.get(), ms.length, ms[ms.length / 2], ms[ms.length * 99 / 100], ms[ms.length - 1]);
        assertEquals(List.of(), List.copyOf(problems));
        assertEquals(written[0], received.get(), "every byte written arrived, on the one connection opened before the faults");
        assertEquals(0, java.util.Arrays.stream(ms).filter(m -> m >= REPLY_WITHIN_MS).count(), "replies within 1 s");
        assertEquals(3, rig.logLines(Level.WARNING, "lost the simulator at 127.0.0.1:" + rig.sim.port()), rig.log.toString());
        assertEquals(3, rig.logLines(Level.INFO, "answers again"), rig.log.toString());
        assertEquals(List.of("A", "B"), rig.server.hub.getListOfRegisteredRobots());
    }

    /** Waits until the log says the simulator is lost for the n-th time, then for service while it is. */
    private void fault(int n, String what) {
        Wait.until("the log says " + what, () -> rig.logLines(Level.WARNING, "lost the simulator") == n);
        servedFor("while " + what);
        assertEquals(n, rig.logLines(Level.WARNING, "lost the simulator"), what + ", said once: " + rig.log);
        assertEquals(n - 1, rig.logLines(Level.INFO, "answers again"), "not back yet while " + what);
    }

    private void back(int n, String what) {
        Wait.until("the log says " + what, () -> rig.logLines(Level.INFO, "answers again") == n);
        servedFor("after " + what);
    }

    /** Data flows and five more control replies come. */
    private void servedFor(String when) {
        long bytes = received.get();
        int answered = replies.get();
        Wait.until("data flows and replies come " + when, () -> received.get() >= bytes + 10 * BLOCK && replies.get() >= answered + 5);
    }

    private void ask(TestRobot robot, String command, String expected) {
        long start = System.nanoTime();
        try {
            String reply = robot.ask(command);
            replyMs.add(TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start));
            replies.incrementAndGet();
            if (!reply.equals(expected)) {
                problems.add(command + " => " + reply + " (not " + expected + ")");
            }
        } catch (IOException e) {
            problems.add(command + ": " + e);
        }
    }

    /** Reads the stream to its end, each byte checked against the sequence. */
    private Void readInOrder(InputStream in) throws IOException {
        byte[] block = new byte[8192];
        byte[] expected = new byte[8192];
        int read;
        while ((read = in.read(block)) >= 0) {
            Sockets.sequence(expected, received.get());
            for (int i = 0; i < read; i++) {
                if (block[i] != expected[i]) {
                    problems.add("byte " + (received.get() + i) + " out of order");
                    return null;
                }
            }
            received.addAndGet(read);
        }
        return null;
    }
}
