package org.usarsim.wss.routes;

import java.util.List;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * What makes one route better than another (docs/routes.md): with links shaped, the larger rate
 * one stream could have over the whole route, then the fewer hops; without, the stronger weakest
 * hop (dBm), then the fewer hops. The rate bound of a route is the shaping's own: with shared
 * airtime (docs/shaping.md, rule 2) a relay's radio carries the stream twice, in on hop i at
 * r(i) and out on hop i+1 at r(i+1), so the stream's rate T needs T/r(i) + T/r(i+1) of that radio's
 * second: T is at most r(i) r(i+1) / (r(i) + r(i+1)) at every relay, and at most r(1) for a route of
 * one hop; without shared airtime each hop is limited by its own rate only.
 */
public enum RouteRule {
    /** Links not shaped: the strongest weakest hop. */
    STRONGEST,
    /** Links shaped, each direction by its own rate only ({@code wss.shaping.airtime = false}): the fastest slowest hop. */
    FASTEST,
    /** Links shaped over shared airtime: the largest bound of one stream through the relays' radios. */
    FASTEST_SHARED_AIRTIME;

    /** The rule for these shaping settings. */
    public static RouteRule of(ShapingConfig shaping) {
        if (!shaping.on()) {
            return STRONGEST;
        }
        return shaping.airtime() ? FASTEST_SHARED_AIRTIME : FASTEST;
    }

    /** Whether routes have a rate (links are shaped). */
    public boolean shaped() {
        return this != STRONGEST;
    }

    /** An unknown strength ranks below every known one. */
    static final double UNKNOWN_STRENGTH = -Double.MAX_VALUE;

    /** A route of the one hop: its rank. */
    double first(Hop hop) {
        if (this == STRONGEST) {
            return Double.isNaN(hop.strength()) ? UNKNOWN_STRENGTH : hop.strength();
        }
        return hop.bitsPerSecond();
    }

    /** The rank a route keeps at most when it goes on by {@code next}, after a hop of rate {@code inRate} into the relay. */
    double relayed(long inRate, Hop next) {
        if (this == FASTEST_SHARED_AIRTIME) {
            return relayBound(inRate, next.bitsPerSecond());
        }
        return first(next);
    }

    /**
     * A relay's bound: the rate T of one stream in at {@code in} and out at {@code out} through one
     * radio, T/in + T/out at most 1: in x out / (in + out), in whole bit/s rounded down.
     */
    public static long relayBound(long in, long out) {
        if (in <= 0 || out <= 0) {
            return 0;
        }
        long high = Math.multiplyHigh(in, out);
        long low = in * out;
        if (high == 0 && low >= 0) {
            return low / (in + out);
        }
        return (long) Math.floor((double) in * out / ((double) in + out));
    }

    /** The rate bound of one stream over these hops, in order (0 when links are not shaped). */
    public long bound(List<Hop> hops) {
        if (this == STRONGEST || hops.isEmpty()) {
            return 0;
        }
        long bound = Long.MAX_VALUE;
        for (int i = 0; i < hops.size(); i++) {
            long here = this == FASTEST_SHARED_AIRTIME && i > 0
                    ? relayBound(hops.get(i - 1).bitsPerSecond(), hops.get(i).bitsPerSecond())
                    : hops.get(i).bitsPerSecond();
            bound = Math.min(bound, here);
        }
        return bound;
    }

    /** The weakest of these hops: the slowest with links shaped (then the weakest), the weakest in dBm without; the first of equals. */
    Hop weakest(List<Hop> hops) {
        Hop weakest = null;
        for (Hop hop : hops) {
            if (weakest == null || weaker(hop, weakest)) {
                weakest = hop;
            }
        }
        return weakest;
    }

    private boolean weaker(Hop hop, Hop than) {
        if (this != STRONGEST && hop.bitsPerSecond() != than.bitsPerSecond()) {
            return hop.bitsPerSecond() < than.bitsPerSecond();
        }
        return STRONGEST.first(hop) < STRONGEST.first(than);
    }
}
