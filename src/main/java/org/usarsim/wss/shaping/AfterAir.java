package org.usarsim.wss.shaping;

/**
 * A stage of a shaped direction after its airtime (docs/shaping.md, "Stages"): when the bytes
 * whose last bit is on the air at a time may be written. The {@link Delay} is the one in use; a
 * delay's jitter, or a TCP link's losses (the wait for a retransmission), would be stages of
 * their own, chained after it with {@link #then}. A {@link ShapedFlow} asks it once for each
 * grant, and again for the grants a change of rate or delay counts again; it writes the bytes in
 * order whatever the stage says, so a grant due before the one ahead of it waits for it.
 */
interface AfterAir {

    /** When the bytes whose last bit is on the air at {@code offAirNs} may be written, at {@code offAirNs} or later. */
    long dueAt(long offAirNs);

    /** How long it holds bytes, at most or as a rule: what a direction's capacity keeps room for besides its queue. */
    long holdsNs();

    /** This stage, then {@code next}. */
    default AfterAir then(AfterAir next) {
        AfterAir first = this;
        return new AfterAir() {
            @Override
            public long dueAt(long offAirNs) {
                return next.dueAt(first.dueAt(offAirNs));
            }

            @Override
            public long holdsNs() {
                return first.holdsNs() + next.holdsNs();
            }
        };
    }
}
