package org.usarsim.wss.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.protocol.Replies;

/**
 * The robots a check registers on a headless WSS (DistanceOnly, {@code distance.n = 3}), each with
 * its control connection and when its INIT was sent; what their GETSS shows against where they
 * stand, and whether the WSS's log says it kicked them.
 */
final class RegisteredRobots implements AutoCloseable {

    /** DistanceOnly's path loss with {@code distance.n = 3}: range 55.6 m. */
    static final PathLoss N3 = new PathLoss(-49.67, 3, 2, -93);

    /** A pair of robots and how far apart they stand. */
    record Pair(String from, String to, double metres) {
        @Override
        public String toString() {
            return String.format(Locale.ROOT, "%s-%s %.1f m", from, to, metres);
        }
    }

    private final WssProcess wss;
    private final Map<String, ControlClient> robots = new LinkedHashMap<>();
    private final Map<String, Long> inits = new LinkedHashMap<>();

    RegisteredRobots(WssProcess wss) {
        this.wss = wss;
    }

    /** Sends the robot's INIT; its accept port is only named, never listened on. */
    void register(String name) throws IOException {
        inits.put(name, System.nanoTime());
        robots.put(name, new ControlClient(wss.controlPort, name, 40001 + robots.size()));
    }

    /** Sends the robots' INITs one after another. */
    void register(List<String> names) throws IOException {
        for (String name : names) {
            register(name);
        }
    }

    /** When the robot's INIT was sent (System.nanoTime). */
    long init(String name) {
        return inits.get(name);
    }

    /** What the robot's GETSS of the other answers now. */
    String getss(Pair pair) throws IOException {
        return robots.get(pair.from()).ask("GETSS {Robot " + pair.to() + "}");
    }

    /** The GETSS reply of a pair that stands this far apart. */
    static String expected(Pair pair) {
        return Replies.signal(pair.to(), N3.strength(pair.metres()));
    }

    /** Asks the pair's GETSS every 20 ms until it shows the strength of its distance: when it did; -1 when not by the deadline. */
    long awaitShown(Pair pair, long deadline) throws IOException, InterruptedException {
        String expected = expected(pair);
        while (System.nanoTime() < deadline) {
            if (getss(pair).equals(expected)) {
                return System.nanoTime();
            }
            Thread.sleep(20);
        }
        return -1;
    }

    /** What {@link #holds} saw: answers right and wrong (the first few wrong ones), connections the WSS closed. */
    record Held(int right, int wrong, List<String> wrongOnes, List<String> closed) {
        boolean well() {
            return right > 0 && wrong == 0 && closed.isEmpty();
        }

        @Override
        public String toString() {
            return right + " GETSS right, " + wrong + " wrong" + (wrongOnes.isEmpty() ? "" : " " + wrongOnes)
                    + (closed.isEmpty() ? "" : ", connections closed by the WSS: " + closed);
        }
    }

    /** Asks every pair's GETSS every 500 ms for {@code millis}: whether each showed the strength of the pair's distance. */
    Held holds(List<Pair> pairs, long millis) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        int right = 0;
        int wrong = 0;
        List<String> wrongOnes = new ArrayList<>();
        List<String> closed = new ArrayList<>();
        while (System.nanoTime() < end) {
            for (Pair pair : pairs) {
                if (closed.contains(pair.from())) {
                    continue;
                }
                try {
                    String reply = getss(pair);
                    if (reply.equals(expected(pair))) {
                        right++;
                    } else if (wrong++ < 3) {
                        wrongOnes.add(pair + ": " + reply);
                    }
                } catch (IOException e) {
                    closed.add(pair.from());
                }
            }
            Thread.sleep(500);
        }
        return new Held(right, wrong, wrongOnes, closed);
    }

    /** How many times the WSS's log said it kicked these robots, by name (only those kicked). */
    Map<String, Long> kicks(List<String> names) {
        Map<String, Long> kicks = new LinkedHashMap<>();
        for (String name : names) {
            long count = wss.linesContaining("kicking " + name + ":");
            if (count > 0) {
                kicks.put(name, count);
            }
        }
        return kicks;
    }

    /** Seconds from the robot's INIT to a time, as text. */
    String since(String name, long nanos) {
        return seconds(nanos - init(name));
    }

    static String seconds(long nanos) {
        return String.format(Locale.ROOT, "%.2f s", nanos / 1e9);
    }

    @Override
    public void close() {
        for (ControlClient robot : robots.values()) {
            try {
                robot.close();
            } catch (IOException e) {
                // closed already (kicked)
            }
        }
    }
}
