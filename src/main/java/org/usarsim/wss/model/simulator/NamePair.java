package org.usarsim.wss.model.simulator;

/** Two robot names in ascending order: one unordered pair. */
public record NamePair(String first, String second) {

    public static NamePair of(String a, String b) {
        return a.compareTo(b) <= 0 ? new NamePair(a, b) : new NamePair(b, a);
    }

    @Override
    public String toString() {
        return first + " <-> " + second;
    }
}
