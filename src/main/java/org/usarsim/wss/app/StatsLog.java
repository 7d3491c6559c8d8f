package org.usarsim.wss.app;

import java.util.List;
import java.util.Locale;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.core.UdpCounts;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.HubSnapshot.RobotEntry;
import org.usarsim.wss.protocol.Strengths;
import org.usarsim.wss.shaping.Bitrate;

/**
 * The headless log's statistics table (wss.statsInterval): every so many seconds, one INFO record
 * with a line per pair of robots, from the hub's snapshot, on a thread of its own
 * ({@code wss-stats-log}). None at all when the interval is 0. With links shaped, each pair's
 * line also has the link's rate each way, and a line per robot follows with its airtime in use
 * (docs/headless.md); without, the table is the one it always was.
 */
final class StatsLog implements AutoCloseable {

    private static final Logger LOG = Logger.getLogger(StatsLog.class.getName());
    static final String HEADER = String.format(Locale.ROOT, "%-24s %-11s %8s %8s %12s %12s %10s %10s %5s %6s %7s %5s  %s",
            "pair A - B", "state", "dBm", "m", "bytes A>B", "bytes B>A", "B/s A>B", "B/s B>A", "conns", "breaks",
            "resumes", "up%", "last close");
    /** The header with links shaped: the rates each way before "last close". */
    static final String SHAPED_HEADER = String.format(Locale.ROOT,
            "%-24s %-11s %8s %8s %12s %12s %10s %10s %12s %12s %5s %6s %7s %5s  %s",
            "pair A - B", "state", "dBm", "m", "bytes A>B", "bytes B>A", "B/s A>B", "B/s B>A", "rate A>B", "rate B>A",
            "conns", "breaks", "resumes", "up%", "last close");
    /** The header of the robots' lines that follow the pairs with links shaped. */
    static final String AIRTIME_HEADER = String.format(Locale.ROOT, "%-24s %8s", "robot", "airtime");
    /** The header of the fixed UDP ports' lines (docs/fixed-ports.md): one a direction that carried datagrams. */
    static final String UDP_HEADER = String.format(Locale.ROOT, "%-24s %12s %14s %14s %13s %12s", "udp from > to", "datagrams",
            "bytes", "dropped broken", "dropped queue", "lost signal");

    private final ScheduledThreadPoolExecutor timer;

    private StatsLog(ScheduledThreadPoolExecutor timer) {
        this.timer = timer;
    }

    /** Logs the hub's table every {@code seconds} from now on; nothing when it is 0. */
    static StatsLog every(int seconds, Hub hub) {
        return every(seconds, hub, false);
    }

    /** As {@link #every(int, Hub)}, with the rates and the airtime when {@code shaped} (wss.shaping = on). */
    static StatsLog every(int seconds, Hub hub, boolean shaped) {
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
                LOG.info(table(hub.snapshot(), shaped));
            } catch (RuntimeException e) {
                LOG.log(Level.WARNING, "could not log the link statistics: " + e, e);
            }
        }, seconds, seconds, TimeUnit.SECONDS);
        return new StatsLog(timer);
    }

    /** The table with links not shaped: a title line, a header line, a line per pair. */
    static String table(List<PairEntry> pairs) {
        return table(new HubSnapshot(List.of(), List.of(), List.of(), pairs), false);
    }

    /**
     * The table: a title line, a header line, a line per pair. With links {@code shaped}, each
     * pair's line has its rate each way before "last close", and when airtime is shared (a
     * robot's is not NaN) a header and a line per robot follow, with the share of the last second
     * its radio was on the air; a line follows for each direction a fixed UDP port carried datagrams in.
     */
    static String table(HubSnapshot snapshot, boolean shaped) {
        List<PairEntry> pairs = snapshot.pairs();
        StringBuilder text = new StringBuilder("link statistics, " + pairs.size() + (pairs.size() == 1 ? " pair" : " pairs"));
        if (!pairs.isEmpty()) {
            text.append('\n').append(shaped ? SHAPED_HEADER : HEADER);
        }
        for (PairEntry pair : pairs) {
            text.append('\n').append(String.format(Locale.ROOT, "%-24s %-11s %8s %8s %12d %12d %10.0f %10.0f ",
                    pair.first() + " - " + pair.second(), pair.state().text(), known(pair.strength()),
                    known(pair.distance()), pair.bytesFirstToSecond(), pair.bytesSecondToFirst(),
                    pair.rateFirstToSecond(), pair.rateSecondToFirst()));
            if (shaped) {
                text.append(String.format(Locale.ROOT, "%12s %12s ", rate(pair.linkRateFirstToSecond()),
                        rate(pair.linkRateSecondToFirst())));
            }
            text.append(String.format(Locale.ROOT, "%5d %6d %7d %5.1f  %s", pair.connections(), pair.breaks(), pair.resumes(),
                    100 * pair.upShare(), pair.lastClose() == null ? "-" : pair.lastClose()));
        }
        boolean udpHeader = false;
        for (PairEntry pair : pairs) {
            for (boolean firstToSecond : new boolean[] {true, false}) {
                UdpCounts.Reading udp = firstToSecond ? pair.udpFirstToSecond() : pair.udpSecondToFirst();
                if (udp.none()) {
                    continue;
                }
                if (!udpHeader) {
                    text.append('\n').append(UDP_HEADER);
                    udpHeader = true;
                }
                String way = firstToSecond ? pair.first() + " > " + pair.second() : pair.second() + " > " + pair.first();
                text.append('\n').append(String.format(Locale.ROOT, "%-24s %12d %14d %14d %13d %12d", way, udp.datagrams(), udp.bytes(),
                        udp.droppedBroken(), udp.droppedQueue(), udp.lost()));
            }
        }
        List<RobotEntry> robots = shaped ? snapshot.robots().stream().filter(robot -> !Double.isNaN(robot.airtime())).toList()
                : List.of();
        if (!robots.isEmpty()) {
            text.append('\n').append(AIRTIME_HEADER);
        }
        for (RobotEntry robot : robots) {
            text.append('\n').append(String.format(Locale.ROOT, "%-24s %6d %%", robot.name(), Math.round(100 * robot.airtime())));
        }
        return text.toString();
    }

    /** A link's rate for people ("54 Mbit/s"), "-" when the pair has none yet. */
    private static String rate(long bitsPerSecond) {
        return bitsPerSecond > 0 ? Bitrate.format(bitsPerSecond) : "-";
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
