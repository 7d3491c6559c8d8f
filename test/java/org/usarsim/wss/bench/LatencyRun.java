package org.usarsim.wss.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.protocol.Replies;

/**
 * One latency run: a headless WSS (DistanceOnly, range 55.6 m with {@code distance.n = 3}) reading
 * a {@link PositionFeed} at a poll interval, A and B registered, B moved between 10 m and 100 m
 * from A; from each move's publish to the new strength on A's GETSS (asked every millisecond),
 * and to the pair's break or resume in the WSS's FINE log.
 */
final class LatencyRun {

    private static final PathLoss N3 = new PathLoss(-49.67, 3, 2, -93);

    private LatencyRun() {
    }

    /** @param more the WSS's settings besides the feed's and the benchmark's own (a stale limit, say) */
    static Latencies measure(PositionFeed feed, int pollMs, int changes, List<String> more) throws Exception {
        List<String> settings = new ArrayList<>(List.of("wss.model=DistanceOnlyPropagationModel", "positions.interval=" + pollMs,
                "distance.n=3", "wss.logLevel=FINE"));
        settings.addAll(feed.wssSettings());
        settings.addAll(more);
        try (WssProcess wss = WssProcess.start(settings.toArray(String[]::new));
                ControlClient a = new ControlClient(wss.controlPort, "A", 40001);
                ControlClient b = new ControlClient(wss.controlPort, "B", 40002)) {
            double at = feed.placeOfB();
            if (awaitStrength(a, at, System.nanoTime() + TimeUnit.SECONDS.toNanos(20)) < 0) {
                throw new IOException("GETSS never showed B at " + at + " m");
            }
            Latencies latencies = new Latencies();
            while (latencies.count() < changes) {
                at = at == 10 ? 100 : 10;
                int lines = wss.lineCount();
                long published = feed.move(at);
                long strength = awaitStrength(a, at, feed.deadline(published));
                if (strength < 0) {
                    latencies.missed();
                    at = at == 10 ? 100 : 10; // the next move, not measured, then GETSS level with it again
                    feed.move(at);
                    if (awaitStrength(a, at, System.nanoTime() + TimeUnit.SECONDS.toNanos(10)) < 0) {
                        throw new IOException("GETSS never showed B at " + at + " m after a missed move");
                    }
                    continue;
                }
                latencies.add(strength - published, linkTime(wss, at, lines) - published);
            }
            latencies.silences(wss.linesContaining("lost the simulator"));
            return latencies;
        }
    }

    /** When the WSS's log said the pair's break (B at 100 m) or resume after line {@code from}; waits up to 10 s. */
    private static long linkTime(WssProcess wss, double at, int from) throws IOException, InterruptedException {
        String event = at == 100 ? "out of range: A - B" : "in range: A - B";
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        for (long link = wss.lineTime(event, from); System.nanoTime() < deadline; link = wss.lineTime(event, from)) {
            if (link >= 0) {
                return link;
            }
            Thread.sleep(1);
        }
        throw new IOException("the WSS's log never said \"" + event + "\"");
    }

    /** Asks A's GETSS for B every millisecond until it shows the strength at {@code metres}: when it did; -1 when not by the deadline. */
    private static long awaitStrength(ControlClient a, double metres, long deadline) throws IOException, InterruptedException {
        String expected = Replies.signal("B", N3.strength(metres));
        while (System.nanoTime() < deadline) {
            if (a.ask("GETSS {Robot B}").equals(expected)) {
                return System.nanoTime();
            }
            Thread.sleep(1);
        }
        return -1;
    }
}
