package org.usarsim.wss.hub.core;

/** Two robots one way, from one to the other: what a pair's condition is kept for (strength, rate and delay may differ each way). */
public record OrderedPair(String from, String to) {
    /**
     * Not the record's {@code 31 * h(a) + h(b)}: a name's own hash is a sum of powers of 31, so
     * that sum makes R12 -> R34 and R13 -> R24 alike; the 9,900 pairs of a 100-robot mesh had
     * 2,788 hashes between them, and the hub's maps of pairs and ports searched trees of them.
     */
    @Override
    public int hashCode() {
        return from.hashCode() * 0x9E3779B9 + to.hashCode();
    }

    public OrderedPair reversed() {
        return new OrderedPair(to, from);
    }

    @Override
    public String toString() {
        return from + " -> " + to;
    }
}
