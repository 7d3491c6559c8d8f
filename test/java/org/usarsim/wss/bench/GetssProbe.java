package org.usarsim.wss.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** Every robot asks GETSS of the next every 100 ms on its control connection; the reply times, from the write to the reply's end. */
final class GetssProbe {

    private static final long EVERY_MS = 100;

    private final List<ControlClient> robots;
    private final List<Long> micros = new ArrayList<>();
    private final List<Thread> threads = new ArrayList<>();
    private volatile boolean running = true;
    private int wrong;

    GetssProbe(List<ControlClient> robots) {
        this.robots = robots;
    }

    void start() {
        for (int i = 0; i < robots.size(); i++) {
            ControlClient robot = robots.get(i);
            String ask = "GETSS {Robot R" + ((i + 1) % robots.size()) + "}";
            Thread thread = new Thread(() -> {
                while (running) {
                    long start = System.nanoTime();
                    try {
                        String reply = robot.ask(ask);
                        long took = (System.nanoTime() - start) / 1000;
                        synchronized (micros) {
                            micros.add(took);
                            if (!reply.startsWith("SS {Robot R")) {
                                wrong++;
                            }
                        }
                        Thread.sleep(EVERY_MS);
                    } catch (IOException | InterruptedException e) {
                        return;
                    }
                }
            }, "getss " + i);
            thread.setDaemon(true);
            thread.start();
            threads.add(thread);
        }
    }

    void stop() throws InterruptedException {
        running = false;
        for (Thread thread : threads) {
            thread.join(5000);
        }
    }

    String summary() {
        synchronized (micros) {
            long[] sorted = micros.stream().mapToLong(Long::longValue).sorted().toArray();
            if (sorted.length == 0) {
                return "no reply";
            }
            return String.format(Locale.ROOT, "%d replies (%d wrong), ms p50 %.1f, p99 %.1f, max %.1f", sorted.length, wrong,
                    RelayBenchmark.percentile(sorted, 50) / 1000, RelayBenchmark.percentile(sorted, 99) / 1000,
                    sorted[sorted.length - 1] / 1000.0);
        }
    }
}
