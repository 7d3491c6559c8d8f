package org.usarsim.wss.hub;

/** Two robots, in no particular order. */
record Pair(String first, String second) {

    static Pair of(String a, String b) {
        return a.compareTo(b) <= 0 ? new Pair(a, b) : new Pair(b, a);
    }

    boolean contains(String robot) {
        return first.equals(robot) || second.equals(robot);
    }
}
