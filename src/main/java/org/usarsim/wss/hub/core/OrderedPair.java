package org.usarsim.wss.hub.core;

/** Two robots one way, from one to the other: what a pair's condition is kept for (strength, rate and delay may differ each way). */
public record OrderedPair(String from, String to) {

    public OrderedPair reversed() {
        return new OrderedPair(to, from);
    }

    @Override
    public String toString() {
        return from + " -> " + to;
    }
}
