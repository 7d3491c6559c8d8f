package org.usarsim.wss.hub;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.LongAdder;
import org.usarsim.wss.model.RobotPair;

/**
 * The counters of one pair of robots since it was first seen. Bytes and connections are added by
 * the link threads without a lock (a {@link LongAdder} each, one add per chunk); the state, its
 * times, the breaks and resumes are changed by the hub under its lock and read under this
 * object's monitor; the throughput is computed by whoever samples the counters
 * ({@link #rates}), not per chunk.
 */
final class PairStats {

    /**
     * The shortest span a throughput is computed over: half a second, so that readers once a
     * second (the window, wss.statsInterval = 1) whose timer fires a little early still get a new
     * figure at every reading, not every other one.
     */
    static final long RATE_SPAN_NS = TimeUnit.MILLISECONDS.toNanos(500);

    final RobotPair pair;
    private final LongAdder bytesFirstToSecond = new LongAdder();
    private final LongAdder bytesSecondToFirst = new LongAdder();
    private final LongAdder connections = new LongAdder();
    private volatile CloseReason lastClose;
    private final long firstSeenNs;
    private PairState state;
    private long stateSinceNs;
    /** Time up before {@link #stateSinceNs}. */
    private long upNs;
    private long breaks;
    private long resumes;
    private long sampledNs;
    private long sampledFirstToSecond;
    private long sampledSecondToFirst;
    private double rateFirstToSecond;
    private double rateSecondToFirst;

    PairStats(RobotPair pair, PairState state, long nowNs) {
        this.pair = pair;
        this.state = state;
        this.firstSeenNs = nowNs;
        this.stateSinceNs = nowNs;
        this.sampledNs = nowNs; // the first span starts when the pair is first seen, at zero bytes
    }

    /** The counter of bytes forwarded from {@code robot} to the other robot of the pair. */
    LongAdder bytesFrom(String robot) {
        return robot.equals(pair.first()) ? bytesFirstToSecond : bytesSecondToFirst;
    }

    /** A connection was established (the WSS reached the target). */
    void opened() {
        connections.increment();
    }

    void closed(CloseReason reason) {
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

    /** @return true when the state changed */
    synchronized boolean moveTo(PairState now, long nowNs) {
        if (now == state) {
            return false;
        }
        if (isUp(state)) {
            upNs += nowNs - stateSinceNs;
        }
        state = now;
        stateSinceNs = nowNs;
        return true;
    }

    synchronized PairState state() {
        return state;
    }

    /** The share of time up since first seen, 0..1 (the state at the first instant when no time has passed). */
    synchronized double upShare(long nowNs) {
        long up = upNs + (isUp(state) ? nowNs - stateSinceNs : 0);
        long seen = nowNs - firstSeenNs;
        return seen <= 0 ? (isUp(state) ? 1 : 0) : Math.min(1, (double) up / seen);
    }

    synchronized long breaks() {
        return breaks;
    }

    synchronized long resumes() {
        return resumes;
    }

    long connections() {
        return connections.sum();
    }

    long bytesFirstToSecond() {
        return bytesFirstToSecond.sum();
    }

    long bytesSecondToFirst() {
        return bytesSecondToFirst.sum();
    }

    CloseReason lastClose() {
        return lastClose;
    }

    /**
     * The throughput each way (bytes/s, first to second then second to first) over the span since
     * the previous sample that was at least {@link #RATE_SPAN_NS} ago, or since the pair was first
     * seen (so bytes moved before the first sample count too); 0 until a span has passed.
     */
    synchronized double[] rates(long nowNs) {
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

    static boolean isUp(PairState state) {
        return state == PairState.UP || state == PairState.FORCED_UP;
    }
}
