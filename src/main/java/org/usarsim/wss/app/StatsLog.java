package org.usarsim.wss.app;

import java.util.List;
import java.util.Locale;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.protocol.Strengths;

/**
 * The headless log's statistics table (wss.statsInterval): every so many seconds, one INFO record
 * with a line per pair of robots, from the hub's snapshot, on a thread of its own
 * ({@code wss-stats-log}). None at all when the interval is 0.
 */
final class StatsLog implements AutoCloseable {

    private static final Logger LOG = Logger.getLogger(StatsLog.class.getName());
    static final String HEADER = String.format(Locale.ROOT, "%-24s %-11s %8s %8s %12s %12s %10s %10s %5s %6s %7s %5s  %s",
            "pair A - B", "state", "dBm", "m", "bytes A>B", "bytes B>A", "B/s A>B", "B/s B>A", "conns", "breaks",
            "resumes", "up%", "last close");

    private final ScheduledThreadPoolExecutor timer;

    private StatsLog(ScheduledThreadPoolExecutor timer) {
        this.timer = timer;
    }

    /** Logs the hub's table every {@code seconds} from now on; nothing when it is 0. */
    static StatsLog every(int seconds, Hub hub) {
        if (seconds <= 0) {
            return new StatsLog(null);
        }
        ScheduledThreadPoolExecutor timer = new ScheduledThreadPoolExecutor(1, task -> {
            Thread thread = new Thread(task, "wss-stats-log");
            thread.setDaemon(true);
            return thread;
        });
        timer.scheduleAtFixedRate(() -> {
            try {
                LOG.info(table(hub.snapshot().pairs()));
            } catch (RuntimeException e) {
                LOG.log(Level.WARNING, "could not log the link statistics: " + e, e);
            }
        }, seconds, seconds, TimeUnit.SECONDS);
        return new StatsLog(timer);
    }

    /** The table: a title line, a header line, a line per pair. */
    static String table(List<PairEntry> pairs) {
        StringBuilder text = new StringBuilder("link statistics, " + pairs.size() + (pairs.size() == 1 ? " pair" : " pairs"));
        if (!pairs.isEmpty()) {
            text.append('\n').append(HEADER);
        }
        for (PairEntry pair : pairs) {
            text.append('\n').append(String.format(Locale.ROOT, "%-24s %-11s %8s %8s %12d %12d %10.0f %10.0f %5d %6d %7d %5.1f  %s",
                    pair.first() + " - " + pair.second(), pair.state().text(), known(pair.strength()),
                    known(pair.distance()), pair.bytesFirstToSecond(), pair.bytesSecondToFirst(),
                    pair.rateFirstToSecond(), pair.rateSecondToFirst(), pair.connections(), pair.breaks(), pair.resumes(),
                    100 * pair.upShare(), pair.lastClose() == null ? "-" : pair.lastClose()));
        }
        return text.toString();
    }

    /** A value as C's %g writes it; "-" for NaN: the model does not know it. */
    private static String known(double value) {
        return Double.isNaN(value) ? "-" : Strengths.format(value);
    }

    @Override
    public void close() {
        if (timer != null) {
            timer.shutdownNow();
        }
    }
}
