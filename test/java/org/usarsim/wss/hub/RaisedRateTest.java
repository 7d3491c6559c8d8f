package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * Issue 27's probe over real sockets: A-B pinned to 1 bit/s beside A-C at 54 Mbit/s, A sending
 * to both flat out, then A-B raised to 54 Mbit/s by FORCE. B's next byte and B's stream at the
 * raised rate must follow within a bound that separates a working WSS from a broken one on a
 * loaded 2-core machine (before issue 27 the next byte came 5 s later); the figures are printed.
 * How soon, on a quiet machine, is the benchmark's (ShapingBenchmark --only raise).
 */
@Tag("slow")
class RaisedRateTest {

    private static final long MS = 1_000_000L;
    /** The bound for B's next byte after the FORCE was sent: the logic's is 2.2 ms (ShapedFlowTest). */
    private static final long NEXT_BYTE_BOUND_NS = 1000 * MS;
    /** What B must have read within {@link #STREAM_BOUND_NS}: 0.3 s at its share, 27 Mbit/s. */
    private static final long STREAM_BYTES = 1_000_000;
    private static final long STREAM_BOUND_NS = 2000 * MS;

    @Test
    void aLinkAt1BitPerSecondRaisedTo54MbitPerSecondMovesAtOnce() throws Exception {
        ShapingConfig shaping = new ShapingConfig(true, RateTable.parse("-72:54M,-87:6M"), 2, true);
        List<Socket> open = new ArrayList<>();
        try (TestHub server = new TestHub(new ScriptedModel(), TestHub.config(true, 65536, 600, 1000, 30).withShaping(shaping, Map.of()));
                TestRobot a = server.robot(); TestRobot b = server.robot(); TestRobot c = server.robot(); TestRobot operator = server.robot()) {
            a.init("A", 5000);
            ServerSocket bAccepts = b.initAccepting("B");
            ServerSocket cAccepts = c.initAccepting("C");
            assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot A} {Peer B} {State Up} {Rate 1} {Delay 0}"));
            assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot A} {Peer C} {State Up} {Rate 54000000}"));
            Socket toB = a.connect(a.dns("B", 0));
            Socket toC = a.connect(a.dns("C", 0));
            open.addAll(List.of(toB, toC));
            Reader atB = new Reader(bAccepts.accept());
            Reader atC = new Reader(cAccepts.accept());
            open.addAll(List.of(atB.socket, atC.socket));
            flatOut(toB);
            flatOut(toC);
            Wait.until("C has read 2 MB beside B at 1 bit/s", () -> atC.total.get() >= 2_000_000);
            long before = atB.total.get();
            assertTrue(before <= 1, "at 1 bit/s B read at most a byte in that time: " + before);

            long sent = System.nanoTime();
            assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot A} {Peer B} {State Up} {Rate 54000000} {Delay 0}"));
            long replied = System.nanoTime();
            long cBefore = atC.total.get();
            long next = atB.awaitAbove(before, sent + 10_000 * MS) - sent;
            long stream = atB.awaitAbove(before + STREAM_BYTES, sent + 10_000 * MS) - sent;
            long cMoved = atC.total.get() - cBefore;
            System.out.printf(Locale.ROOT, "RaisedRateTest: FORCE's round trip %.1f ms; B's next byte %.1f ms after the FORCE was sent,"
                    + " %,d bytes more %.1f ms after (C read %,d meanwhile)%n", (replied - sent) / 1e6, next / 1e6, STREAM_BYTES,
                    stream / 1e6, cMoved);
            assertTrue(next <= NEXT_BYTE_BOUND_NS, "B's next byte " + next / MS + " ms after the FORCE");
            assertTrue(stream <= STREAM_BOUND_NS, "B read " + STREAM_BYTES + " bytes more " + stream / MS + " ms after the FORCE");
            assertTrue(cMoved >= STREAM_BYTES / 2, "C kept moving beside B: " + cMoved + " bytes");
        } finally {
            for (Socket socket : open) {
                socket.close();
            }
        }
    }

    /** Writes zeros to {@code socket} as fast as it takes them, on a thread of its own, until it is closed. */
    private static void flatOut(Socket socket) {
        Thread writer = new Thread(() -> {
            byte[] chunk = new byte[64 * 1024];
            try {
                OutputStream out = socket.getOutputStream();
                while (true) {
                    out.write(chunk);
                }
            } catch (IOException e) {
                // closed at the end of the test
            }
        }, "flat out " + socket.getLocalPort());
        writer.setDaemon(true);
        writer.start();
    }

    /** A robot's end of a link that reads everything, counting it with the time of each read, on a thread of its own. */
    private static final class Reader {
        final Socket socket;
        final AtomicLong total = new AtomicLong();
        /** The time of each read and the total after it. */
        private final List<long[]> reads = new ArrayList<>();

        Reader(Socket socket) {
            this.socket = socket;
            Thread thread = new Thread(this::read, "reader " + socket.getLocalPort());
            thread.setDaemon(true);
            thread.start();
        }

        private void read() {
            byte[] buffer = new byte[64 * 1024];
            try {
                InputStream in = socket.getInputStream();
                int read;
                while ((read = in.read(buffer)) >= 0) {
                    long now = System.nanoTime();
                    synchronized (this) {
                        reads.add(new long[] {now, total.addAndGet(read)});
                        notifyAll();
                    }
                }
            } catch (IOException e) {
                // closed at the end of the test
            }
        }

        /** The time of the read after which the total first exceeded {@code bytes}, waiting for it at most until {@code deadlineNs}. */
        synchronized long awaitAbove(long bytes, long deadlineNs) throws InterruptedException {
            while (total.get() <= bytes) {
                long left = deadlineNs - System.nanoTime();
                assertTrue(left > 0, "read " + total.get() + " bytes, not more than " + bytes + ", by the deadline");
                wait(Math.max(1, left / MS));
            }
            return reads.stream().filter(read -> read[1] > bytes).findFirst().orElseThrow()[0];
        }
    }
}
