package org.usarsim.wss.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.usarsim.wss.hub.CsvEventLog;

/**
 * What the CSV event log costs a link's thread per chunk, and its writer thread per line: one
 * thread calls {@code dataSent} as a link forwarding 64 KiB chunks does (one call every
 * {@code --apart} µs; 50 µs is a link at 1.3 GB/s), the log writing to a file in a temporary
 * folder (deleted after). Each call is timed with {@code System.nanoTime} around it, less what two
 * readings of the clock cost alone; the writer's CPU is its thread's. docs/performance.md, "The
 * CSV event log".
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.EventLogCallBenchmark [--calls 100000] [--apart 50] [--rounds 4]
 * </pre>
 */
public final class EventLogCallBenchmark {

    private EventLogCallBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        int calls = 100_000;
        long apartNanos = 50_000;
        int rounds = 4;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--calls" -> calls = Integer.parseInt(args[++i]);
                case "--apart" -> apartNanos = Long.parseLong(args[++i]) * 1000;
                case "--rounds" -> rounds = Integer.parseInt(args[++i]);
                default -> throw new IllegalArgumentException("unknown argument " + args[i]);
            }
        }
        System.out.printf(Locale.ROOT, "CSV event log, dataSent: %d calls a round, one every %d µs, %d rounds after one unmeasured; load average %s%n",
                calls, apartNanos / 1000, rounds, Files.readString(Path.of("/proc/loadavg")).strip());
        Path dir = Files.createTempDirectory("wss-bench-call");
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        long clock = clockCost();
        try {
            CsvEventLog log = CsvEventLog.create(dir);
            long writer = Thread.getAllStackTraces().keySet().stream().filter(t -> t.getName().equals("wss-event-log")).findFirst()
                    .orElseThrow().getId();
            for (int round = 0; round <= rounds; round++) {
                long writerBefore = threads.getThreadCpuTime(writer);
                long[] took = new long[calls];
                for (int i = 0; i < calls; i++) {
                    long start = System.nanoTime();
                    log.dataSent("Source", "Sink", 65536);
                    long end = System.nanoTime();
                    took[i] = end - start - clock;
                    while (System.nanoTime() < end + apartNanos) {
                        Thread.onSpinWait();
                    }
                }
                Thread.sleep(200); // the writer's last batch of the round: it gathers for 20 ms
                long writerNanos = threads.getThreadCpuTime(writer) - writerBefore;
                if (round > 0) {
                    Arrays.sort(took);
                    System.out.printf(Locale.ROOT, "round %d: the caller %.0f ns a call on average (median %d, p99 %d, max %d µs);"
                            + " the writer %.0f ns of CPU a line%n", round, Arrays.stream(took).average().orElse(0), took[calls / 2],
                            took[calls * 99 / 100], took[calls - 1] / 1000, (double) writerNanos / calls);
                }
            }
            log.close();
            System.out.printf(Locale.ROOT, "the log: %,d bytes%n", Files.size(log.file()));
            Files.delete(log.file());
        } finally {
            Files.delete(dir);
        }
    }

    /** What two readings of System.nanoTime back to back cost, in ns: the median of many. */
    private static long clockCost() {
        long[] costs = new long[1_000_001];
        for (int i = 0; i < costs.length; i++) {
            long start = System.nanoTime();
            costs[i] = System.nanoTime() - start;
        }
        Arrays.sort(costs);
        return costs[costs.length / 2];
    }
}
