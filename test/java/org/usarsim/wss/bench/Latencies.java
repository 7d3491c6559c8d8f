package org.usarsim.wss.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** One {@link LatencyRun}'s figures: publish to GETSS and to the break or resume, in nanoseconds, with the moves it missed. */
final class Latencies {

    private final List<Long> getss = new ArrayList<>();
    private final List<Long> links = new ArrayList<>();
    private int missed;
    private long silences;

    void add(long toGetss, long toLink) {
        getss.add(toGetss);
        links.add(toLink);
    }

    /** A move GETSS did not show before the next one. */
    void missed() {
        missed++;
    }

    /** How many silences of the source the WSS said in the run. */
    void silences(long count) {
        silences = count;
    }

    int count() {
        return getss.size();
    }

    /** Publish to GETSS, ms: the median. */
    double median() {
        return ms(getss, 50);
    }

    /** Publish to GETSS, ms: the 99th percentile. */
    double p99() {
        return ms(getss, 99);
    }

    private static double ms(List<Long> values, double percentile) {
        return RelayBenchmark.percentile(values.stream().mapToLong(Long::longValue).toArray(), percentile) / 1e6;
    }

    /** Issue 31's bound on the median at a poll interval: half the interval plus 20 ms. */
    static double medianBound(int pollMs) {
        return pollMs / 2.0 + 20;
    }

    /** Issue 31's bound on the p99 at a poll interval: the interval plus 50 ms. */
    static double p99Bound(int pollMs) {
        return pollMs + 50.0;
    }

    /** The line of a source: GETSS and break/resume, median and p99, each GETSS figure PASS or FAIL by its bound at this poll. */
    String line(int pollMs) {
        return String.format(Locale.ROOT, "publish -> GETSS median %.1f ms %s, p99 %.1f ms %s; -> break/resume median %.1f ms,"
                + " p99 %.1f ms; %d moves%s%s", median(), median() <= medianBound(pollMs) ? "PASS" : "FAIL", p99(),
                p99() <= p99Bound(pollMs) ? "PASS" : "FAIL", ms(links, 50), ms(links, 99), count(), missed == 0 ? "" : ", " + missed
                + " missed", silences == 0 ? "" : ", " + silences + " silences said");
    }
}
