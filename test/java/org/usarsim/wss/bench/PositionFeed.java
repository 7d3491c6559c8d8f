package org.usarsim.wss.bench;

import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;

/**
 * Where robots A and B are in {@link LatencyRun}: A stands at the origin, B moves along x between
 * two places, at moments of the feed's choosing (random against the WSS's poll), and the feed says
 * when each move was published.
 */
interface PositionFeed extends AutoCloseable {

    /** What the source is, for the report. */
    String label();

    /** The WSS's settings that read this source (positions, its address, topic and type). */
    List<String> wssSettings();

    /** B's x now, from the source (waits for its first word on B); B starts at 10 m unless the source moves it itself. */
    default double placeOfB() throws Exception {
        return 10;
    }

    /** B to {@code x}, or B's next move there when the source moves it itself: when it was published (System.nanoTime). */
    long move(double x) throws Exception;

    /**
     * Until when (System.nanoTime) GETSS may show a move published at {@code published}: after it, the
     * move was missed; 10 s unless the source's next move comes sooner.
     */
    default long deadline(long published) {
        return published + TimeUnit.SECONDS.toNanos(10);
    }

    /** Ends what the source runs for the run, and says what it did (for the report); empty when nothing to say. */
    default String finish() throws Exception {
        return "";
    }

    /** A random moment of the poll: one to two intervals from now, as the benchmark has always waited between moves. */
    static void pause(Random random, int pollMs) throws InterruptedException {
        Thread.sleep(random.nextInt(pollMs) + pollMs);
    }
}
