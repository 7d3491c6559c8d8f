package org.usarsim.wss;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.Wait;

/** The queue and thread behind the event log and the recording: order, the bound, the writer's sleep and wake-up, the close. */
class QueuedWriterTest {

    private static final Logger LOG = Logger.getLogger(QueuedWriterTest.class.getName());

    /** Writes each item as a line; a DROPPED line after a batch that dropped some. */
    private static final QueuedWriter.Format<String> LINES = new QueuedWriter.Format<>() {
        @Override
        public void append(StringBuilder text, String item) {
            text.append(item).append(System.lineSeparator());
        }

        @Override
        public void dropped(StringBuilder text, long count) {
            text.append("DROPPED ").append(count).append(System.lineSeparator());
        }
    };

    @Test
    void anItemOfferedJustAsTheWriterGoesToSleepWakesIt() throws Exception {
        StuckWriter out = new StuckWriter();
        out.release.countDown();
        QueuedWriter<String> writer = new QueuedWriter<>("test-writer", LOG, "the test file", out, 16, LINES);
        // Each item is offered the moment the one before is written: the writer is then between its
        // write and its sleep, the moment an offer and the writer's last look race.
        for (int i = 0; i < 40; i++) {
            String item = "item " + i;
            assertTrue(writer.offer(item));
            int written = i + 1;
            Wait.until(item + " is written", () -> out.lines().size() == written);
            assertEquals(item, out.lines().get(i));
        }
        writer.close();
        assertTrue(out.closed);
    }

    @Test
    void theQueueHoldsAtMostItsCapacityAndCloseWritesItAllWhenFull() throws Exception {
        StuckWriter out = new StuckWriter();
        QueuedWriter<String> writer = new QueuedWriter<>("test-writer", LOG, "the test file", out, 4, LINES);
        assertTrue(writer.offer("first"));
        assertTrue(out.stuck.await(5, TimeUnit.SECONDS), "the writer holds the first item in its write");
        List<Boolean> taken = new ArrayList<>();
        for (int i = 1; i <= 9; i++) {
            taken.add(writer.offer("item " + i));
        }
        assertEquals(List.of(true, true, true, true, false, false, false, false, false), taken, "four queued, five dropped");

        Thread closing = new Thread(writer::close, "closing");
        closing.start(); // the end goes in although the queue is full, and close waits for the writer
        out.release.countDown();
        closing.join(TimeUnit.SECONDS.toMillis(10));
        assertFalse(closing.isAlive());
        assertTrue(out.closed);
        assertFalse(writer.offer("after the close"));
        assertEquals(List.of("first", "item 1", "item 2", "item 3", "item 4", "DROPPED 5"), out.lines());
    }

    @Test
    void concurrentOffersKeepEachThreadsOrderAndEveryItemIsWrittenOrCounted() throws Exception {
        StuckWriter out = new StuckWriter();
        out.release.countDown();
        QueuedWriter<String> writer = new QueuedWriter<>("test-writer", LOG, "the test file", out, 256, LINES);
        int threads = 4;
        int each = 20_000;
        Thread[] offering = new Thread[threads];
        for (int t = 0; t < threads; t++) {
            int thread = t;
            offering[t] = new Thread(() -> {
                for (int i = 0; i < each; i++) {
                    writer.offer(thread + ":" + i);
                }
            }, "offering " + t);
            offering[t].start();
        }
        for (Thread thread : offering) {
            thread.join(TimeUnit.SECONDS.toMillis(30));
            assertFalse(thread.isAlive());
        }
        writer.close();

        long dropped = 0;
        int[] last = new int[threads];
        Arrays.fill(last, -1);
        int written = 0;
        for (String line : out.lines()) {
            if (line.startsWith("DROPPED ")) {
                dropped += Long.parseLong(line.substring("DROPPED ".length()));
                continue;
            }
            int thread = Integer.parseInt(line.substring(0, line.indexOf(':')));
            int index = Integer.parseInt(line.substring(line.indexOf(':') + 1));
            assertTrue(index > last[thread], "thread " + thread + "'s " + index + " after its " + last[thread]);
            last[thread] = index;
            written++;
        }
        assertEquals(threads * each, written + dropped, "written " + written + ", dropped " + dropped);
    }
}
