package org.usarsim.wss.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.TimeUnit;

/**
 * A and B in the world server's rosbridge side ({@link WorldProcess}), B jumping by its world file's
 * timed points ({@code at}: a jump takes a microsecond) at random moments after a lead for the
 * WSS's start. The world server is known only from outside: a move's publish is when
 * {@link TopicWatcher}, a subscriber of the benchmark's own with no throttle and no queue, first
 * sees B's new place (the world server's one publisher of {@code /gazebo/model_states} at {@code --ros-rate}: the
 * watcher, with no throttle, gets each message as it is published; the WSS, throttled to 20 ms,
 * too at 5 and 20 Hz).
 */
final class WorldFeed implements PositionFeed {

    /** When B first jumps, in seconds of the world's clock: time for the WSS to start and A and B to register. */
    private static final double LEAD_SECONDS = 8;
    /** The least time between two jumps, beside a poll interval and a random part of one: room for a late GETSS. */
    private static final int SETTLE_MS = 1000;

    private final int hz;
    private final int pollMs;
    private final WorldProcess world;
    private final TopicWatcher watcher;
    /** The index of the next place of B to look at in {@link #watcher}. */
    private int from;

    /** The world server's publishers at {@code hz} ({@code --ros-rate}). */
    WorldFeed(int hz, int pollMs, int changes) throws IOException, InterruptedException {
        this.hz = hz;
        this.pollMs = pollMs;
        world = WorldProcess.start(worldLines(pollMs, 2 * changes + 20), hz);
        watcher = TopicWatcher.open(world.url(), "/gazebo/model_states", "B");
    }

    /** A at the origin, B at 10 m, then jumping between 100 m and 10 m {@code jumps} times. */
    private static List<String> worldLines(int pollMs, int jumps) {
        Random random = new Random(23);
        List<String> lines = new ArrayList<>(List.of("robot A 0,0,0", "robot B 10,0,0", "at B 0 10,0,0"));
        double seconds = LEAD_SECONDS;
        double x = 10;
        for (int i = 0; i < jumps; i++) {
            lines.add(String.format(Locale.ROOT, "at B %.6f %.0f,0,0", seconds, x));
            x = x == 10 ? 100 : 10;
            lines.add(String.format(Locale.ROOT, "at B %.6f %.0f,0,0", seconds + 1e-6, x));
            seconds += (SETTLE_MS + pollMs + random.nextInt(pollMs)) / 1000.0;
        }
        return lines;
    }

    @Override
    public String label() {
        return "world server's rosbridge (--ros-rate " + hz + ")";
    }

    @Override
    public List<String> wssSettings() {
        return List.of("positions=rosbridge", "rosbridge.url=" + world.url());
    }

    @Override
    public double placeOfB() throws IOException, InterruptedException {
        TopicWatcher.Seen now = watcher.latest(System.nanoTime() + TimeUnit.SECONDS.toNanos(20));
        from = now.index() + 1;
        return now.x();
    }

    @Override
    public long move(double x) throws IOException, InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos((long) LEAD_SECONDS) + TimeUnit.MILLISECONDS.toNanos(
                SETTLE_MS + 2L * pollMs);
        TopicWatcher.Seen seen = watcher.await(x, from, deadline);
        from = seen.index() + 1;
        return seen.nanos();
    }

    @Override
    public long deadline(long published) {
        return published + TimeUnit.MILLISECONDS.toNanos(SETTLE_MS + pollMs - 50);
    }

    @Override
    public void close() throws InterruptedException {
        watcher.close();
        world.close();
    }
}
