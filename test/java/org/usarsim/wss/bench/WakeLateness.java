package org.usarsim.wss.bench;

import java.nio.channels.Selector;
import java.util.Arrays;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

/**
 * How late a link thread wakes on this machine now (docs/routes.md, "The bound against
 * reality"): waits of 0.2 to 4 ms as a link's loop waits (whole milliseconds on a selector, the
 * rest parked), each until its time has passed, and how long after its time each wait ended. The
 * mean is the lateness {@code shaping.RelayChainSimulation} takes; run it beside a benchmark to
 * know the load the benchmark ran under.
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.WakeLateness [--seconds 20]
 * </pre>
 */
public final class WakeLateness {

    private WakeLateness() {
    }

    public static void main(String[] args) throws Exception {
        int seconds = args.length > 1 && args[0].equals("--seconds") ? Integer.parseInt(args[1]) : 20;
        Random random = new Random(34);
        long[] late = new long[seconds * 2000];
        int count = 0;
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        try (Selector selector = Selector.open()) {
            while (System.nanoTime() - end < 0 && count < late.length) {
                long wait = 200_000 + random.nextInt(3_800_000);
                long due = System.nanoTime() + wait;
                for (long left = wait; left > 0; left = due - System.nanoTime()) {
                    if (left >= 1_000_000) {
                        selector.select(TimeUnit.NANOSECONDS.toMillis(left));
                    } else {
                        LockSupport.parkNanos(left);
                    }
                }
                late[count++] = System.nanoTime() - due;
            }
        }
        long[] sorted = Arrays.copyOf(late, count);
        Arrays.sort(sorted);
        double mean = Arrays.stream(sorted).average().orElse(0);
        System.out.printf(Locale.ROOT, "%d wake-ups: late by mean %.3f ms, median %.3f, p90 %.3f, p99 %.3f, max %.3f ms%n", count,
                mean / 1e6, at(sorted, 0.5), at(sorted, 0.9), at(sorted, 0.99), sorted[count - 1] / 1e6);
    }

    private static double at(long[] sorted, double quantile) {
        return sorted[(int) Math.min(sorted.length - 1, quantile * sorted.length)] / 1e6;
    }
}
