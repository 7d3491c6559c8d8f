package org.usarsim.wss.hub.core;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.LongAdder;
import org.usarsim.wss.model.RobotPair;

/**
 * The counters of one pair of robots since it was first seen. Bytes and connections are added by
 * the link threads without a lock (a {@link LongAdder} each, one add per chunk); the state, its
 * times, the breaks and resumes are changed by the core (under the hub's lock) and read under this
 * object's monitor; the throughput is computed by whoever samples the counters
 * ({@link #rates}), not per chunk.
 */
public final class PairStats {

    /**
     * The shortest span a throughput is computed over: half a second, so that readers once a
     * second (the window, wss.statsInterval = 1) whose timer fires a little early still get a new
     * figure at every reading, not every other one.
     */
    public static final long RATE_SPAN_NS = TimeUnit.MILLISECONDS.toNanos(500);

    public final RobotPair pair;
    private final LongAdder bytesFirstToSecond = new LongAdder();
    private final LongAdder bytesSecondToFirst = new LongAdder();
    private final LongAdder connections = new LongAdder();
    private final UdpCounts udpFirstToSecond = new UdpCounts();
    private final UdpCounts udpSecondToFirst = new UdpCounts();
    private volatile CloseReason lastClose;
    private final long firstSeenNs;
    private PairState state;
    /** Both robots are registered: only then can the pair talk, whatever its state. */
    private boolean present;
    private long stateSinceNs;
    /** Time up (and present) before {@link #stateSinceNs}. */
    private long upNs;
    private long breaks;
    private long resumes;
    private long sampledNs;
    private long sampledFirstToSecond;
    private long sampledSecondToFirst;
    private double rateFirstToSecond;
    private double rateSecondToFirst;

    PairStats(RobotPair pair, PairState state, boolean present, long nowNs) {
        this.pair = pair;
        this.state = state;
        this.present = present;
        this.firstSeenNs = nowNs;
        this.stateSinceNs = nowNs;
        this.sampledNs = nowNs; // the first span starts when the pair is first seen, at zero bytes
    }

    /** The counter of bytes forwarded from {@code robot} to the other robot of the pair. */
    public LongAdder bytesFrom(String robot) {
        return robot.equals(pair.first()) ? bytesFirstToSecond : bytesSecondToFirst;
    }

    /** The datagrams of the pair's fixed UDP ports from {@code robot} to the other robot of the pair. */
    public UdpCounts udpFrom(String robot) {
        return robot.equals(pair.first()) ? udpFirstToSecond : udpSecondToFirst;
    }

    /** A connection was established (the WSS reached the target). */
    public void opened() {
        connections.increment();
    }

    public void closed(CloseReason reason) {
        lastClose = reason;
    }

    /** The model broke ({@code true}) or resumed the pair. */
    synchronized void modelChanged(boolean broke) {
        if (broke) {
            breaks++;
        } else {
            resumes++;
        }
    }

    /**
     * The pair's state now, and whether both robots are registered now (a pair is up only for the
     * time both are: the share of time up says how long the two could talk).
     *
     * @return true when the state changed
     */
    synchronized boolean moveTo(PairState now, boolean bothPresent, long nowNs) {
        if (now == state && bothPresent == present) {
            return false;
        }
        if (talking()) {
            upNs += nowNs - stateSinceNs;
        }
        boolean changed = now != state;
        state = now;
        present = bothPresent;
        stateSinceNs = nowNs;
        return changed;
    }

    /** One of the robots left: the time up stops counting, the state shown stays. */
    synchronized void absent(long nowNs) {
        moveTo(state, false, nowNs);
    }

    private boolean talking() {
        return state.isUp() && present;
    }

    public synchronized PairState state() {
        return state;
    }

    /**
     * The share of time since first seen that the pair was up with both robots registered, 0..1
     * (whether it is so now, at the first instant when no time has passed).
     */
    public synchronized double upShare(long nowNs) {
        long up = upNs + (talking() ? nowNs - stateSinceNs : 0);
        long seen = nowNs - firstSeenNs;
        return seen <= 0 ? (talking() ? 1 : 0) : Math.min(1, (double) up / seen);
    }

    public synchronized long breaks() {
        return breaks;
    }

    public synchronized long resumes() {
        return resumes;
    }

    public long connections() {
        return connections.sum();
    }

    public long bytesFirstToSecond() {
        return bytesFirstToSecond.sum();
    }

    public long bytesSecondToFirst() {
        return bytesSecondToFirst.sum();
    }

    public CloseReason lastClose() {
        return lastClose;
    }

    /**
     * The throughput each way (bytes/s, first to second then second to first) over the span since
     * the previous sample that was at least {@link #RATE_SPAN_NS} ago, or since the pair was first
     * seen (so bytes moved before the first sample count too); 0 until a span has passed.
     */
    public synchronized double[] rates(long nowNs) {
        long toSecond = bytesFirstToSecond.sum();
        long toFirst = bytesSecondToFirst.sum();
        if (nowNs - sampledNs >= RATE_SPAN_NS) {
            double seconds = (nowNs - sampledNs) / 1e9;
            rateFirstToSecond = (toSecond - sampledFirstToSecond) / seconds;
            rateSecondToFirst = (toFirst - sampledSecondToFirst) / seconds;
            sampledNs = nowNs;
            sampledFirstToSecond = toSecond;
            sampledSecondToFirst = toFirst;
        }
        return new double[] {rateFirstToSecond, rateSecondToFirst};
    }
}
