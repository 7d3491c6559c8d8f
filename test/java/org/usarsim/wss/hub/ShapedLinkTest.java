package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.security.MessageDigest;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * Links shaped like radio over real loopback sockets (docs/shaping.md): the rate from the
 * strength, an operator's pinned rate and delay, a rate that follows the strength, RATE events,
 * and nothing lost. Bounds are generous: these check the wiring; the accuracy is the benchmark's
 * and the pure classes' (org.usarsim.wss.shaping, on a moved clock).
 */
@Tag("slow")
class ShapedLinkTest {

    private static final RateTable TABLE = RateTable.parse("-50:8M,-70:2M,-90:1M");

    @Test
    void aPinnedRateCarriesABulkTransferAtAboutThatRateAndLosesNothing() throws Exception {
        ScriptedModel model = new ScriptedModel();
        try (TestHub server = shaped(model, 2); TestRobot r1 = server.robot(); TestRobot r2 = server.robot();
                TestRobot operator = server.robot()) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot R1} {Peer R2} {State Up} {Rate 4M}"));
            byte[] bytes = Sockets.randomBytes(1_000_000, 16); // 2 s at 4 Mbit/s
            ExecutorService pool = Executors.newSingleThreadExecutor();
            try (Socket source = r2.connect(r2.dns("R1", 0)); Socket target = r1Accepts.accept()) {
                long start = System.nanoTime();
                Future<?> sending = pool.submit(() -> {
                    OutputStream out = source.getOutputStream();
                    out.write(bytes);
                    out.flush();
                    return null;
                });
                byte[] received = Sockets.readExactlyBytes(target.getInputStream(), bytes.length);
                double seconds = (System.nanoTime() - start) / 1e9;
                sending.get(10, TimeUnit.SECONDS);
                assertArrayEquals(sha256(bytes), sha256(received), "every byte, in order");
                double bitsPerSecond = bytes.length * 8 / seconds;
                assertTrue(bitsPerSecond > 4e6 * 0.7 && bitsPerSecond < 4e6 * 1.1, bitsPerSecond + " bit/s at 4M");
            } finally {
                pool.shutdownNow();
            }
        }
    }

    /**
     * Issue 27, item 3: a saturating stream through a shaped link is held back by TCP, not queued
     * in the WSS. At 2 Mbit/s, delay 2 ms and the default queue (20 ms), what the sender has
     * written and the receiver not yet read stays within what docs/shaping.md ("The queue")
     * bounds it by: the flow's 5.5 KB, the WSS's two socket buffers of this machine's floor
     * (64 KiB each, which the kernel doubles), the sender's own 64 KiB (doubled too) and a chunk
     * in hand on either side: 512 KiB at most. Before issue 27 the link's 4 MiB buffers held
     * megabytes (12.5 s of a 1 Mbit/s stream).
     */
    @Test
    void aSaturatingStreamWaitsInTheSenderNotInTheWss() throws Exception {
        ScriptedModel model = new ScriptedModel();
        try (TestHub server = shaped(model, 2); TestRobot r1 = server.robot(); TestRobot r2 = server.robot();
                TestRobot operator = server.robot()) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot R1} {Peer R2} {State Up} {Rate 2M} {Delay 2}"));
            AtomicLong written = new AtomicLong();
            ExecutorService pool = Executors.newSingleThreadExecutor();
            try (Socket source = r2.connect(r2.dns("R1", 0)); Socket target = r1Accepts.accept()) {
                source.setSendBufferSize(64 * 1024);
                Future<?> sending = pool.submit(() -> {
                    OutputStream out = source.getOutputStream();
                    byte[] chunk = new byte[16 * 1024];
                    while (!Thread.currentThread().isInterrupted()) {
                        out.write(chunk);
                        written.addAndGet(chunk.length);
                    }
                    return null;
                });
                InputStream in = target.getInputStream();
                byte[] buffer = new byte[64 * 1024];
                long received = 0;
                long most = 0;
                while (received < 750_000) { // 3 s at 2 Mbit/s; the queue is standing after the first
                    int read = in.read(buffer);
                    assertTrue(read > 0, "the stream goes on");
                    received += read;
                    if (received > 250_000) {
                        most = Math.max(most, written.get() - received);
                    }
                }
                System.out.println("written and not yet read, at most: " + most + " bytes");
                assertTrue(most <= 512 * 1024, most + " bytes written and not yet read");
                sending.cancel(true);
            } finally {
                pool.shutdownNow();
            }
        }
    }

    @Test
    void aRoundTripTakesTwiceTheDelayAtLeast() throws Exception {
        try (TestHub server = shaped(new ScriptedModel(), 50); TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            try (Socket source = r2.connect(r2.dns("R1", 0)); Socket target = r1Accepts.accept()) {
                InputStream echoIn = target.getInputStream();
                OutputStream echoOut = target.getOutputStream();
                byte[] ping = new byte[64];
                long best = Long.MAX_VALUE;
                for (int i = 0; i < 5; i++) {
                    long start = System.nanoTime();
                    source.getOutputStream().write(ping);
                    echoOut.write(Sockets.readExactlyBytes(echoIn, 64));
                    Sockets.readExactlyBytes(source.getInputStream(), 64);
                    best = Math.min(best, System.nanoTime() - start);
                }
                double ms = best / 1e6;
                assertTrue(ms >= 100 && ms < 100 + 50, ms + " ms for a round trip at 50 ms each way");
            }
        }
    }

    @Test
    void theRateFollowsTheStrengthAndIsSaidOnceAChange() throws Exception {
        ScriptedModel model = new ScriptedModel();
        model.strength("R2", "R1", -40);
        model.strength("R1", "R2", -40);
        List<String> rates = new CopyOnWriteArrayList<>();
        try (TestHub server = shaped(model, 2); TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            server.hub.addListener(new WssEventListener() {
                @Override
                public void rateChanged(String from, String to, long bitsPerSecond) {
                    rates.add(from + ">" + to + " " + bitsPerSecond);
                }
            });
            r1.initAccepting("R1");
            r2.init("R2", 6000);
            r2.dns("R1", 0);
            Wait.until("both ways at the top rate, 8M", () -> rates.containsAll(List.of("R2>R1 8000000", "R1>R2 8000000")));
            assertEquals(8_000_000, rateOf(server, "R1", "R2"));

            model.strength("R2", "R1", -80); // R1 drives away, heard weaker one way
            Wait.until("R2 -> R1 slows to 1M within a poll", () -> rates.contains("R2>R1 1000000"));
            assertEquals(1_000_000, server.hub.snapshot().pairs().get(0).linkRateSecondToFirst(), rates + " " + server.hub.snapshot().pairs());
            assertEquals(8_000_000, rateOf(server, "R1", "R2"), "the other way keeps its rate");
            long asked = model.strengthsAsked();
            Wait.until("the sampler polled a few more times", () -> model.strengthsAsked() >= asked + 10);
            assertEquals(3, rates.size(), "said once per change, never per poll: " + rates);

            model.links().breakConnectionsForPair("R1", "R2"); // issue 26, item 5: a broken pair shows no rate
            HubSnapshot.PairEntry broken = server.hub.snapshot().pairs().get(0);
            assertEquals(List.of(PairState.BROKEN, 0L, 0L), List.of(broken.state(), broken.linkRateFirstToSecond(),
                    broken.linkRateSecondToFirst()), broken.toString());
        }
    }

    @Test
    void aBadRateOrDelayInFORCEGetsAClearErrorAndTheSessionGoesOn() throws Exception {
        try (TestHub server = shaped(new ScriptedModel(), 2); TestRobot operator = server.robot()) {
            assertEquals("ERROR {Reason Rate.Must.Be.A.Bit.Rate}", operator.ask("FORCE {Robot A} {Peer B} {State Up} {Rate fast}"));
            assertEquals("ERROR {Reason Rate.Must.Be.A.Bit.Rate}", operator.ask("FORCE {Robot A} {Peer B} {State Up} {Rate -1M}"));
            assertEquals("ERROR {Reason Delay.Must.Be.0.To.10000.Ms}", operator.ask("FORCE {Robot A} {Peer B} {State Up} {Delay 10001}"));
            assertEquals("ERROR {Reason Rate.And.Delay.Need.State.Up}", operator.ask("FORCE {Robot A} {Peer B} {State Down} {Rate 1M}"));
            assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot A} {Peer B} {State Up} {Rate 1M} {Delay 50}"));
        }
    }

    private static long rateOf(TestHub server, String first, String second) {
        return server.hub.snapshot().pairs().stream().filter(p -> p.first().equals(first) && p.second().equals(second))
                .findFirst().orElseThrow().linkRateFirstToSecond();
    }

    private static TestHub shaped(ScriptedModel model, int delayMs) throws Exception {
        ShapingConfig shaping = new ShapingConfig(true, TABLE, delayMs, true);
        return new TestHub(model, TestHub.config(true, 65536, 600, 1000, 30).withShaping(shaping, Map.of()));
    }

    private static byte[] sha256(byte[] bytes) throws Exception {
        return MessageDigest.getInstance("SHA-256").digest(bytes);
    }
}
