package org.usarsim.wss.model;

/** Two robot names in no particular order, kept in ascending order: one unordered pair, the same whichever way it was named. */
public record RobotPair(String first, String second) {

    public static RobotPair of(String a, String b) {
        return a.compareTo(b) <= 0 ? new RobotPair(a, b) : new RobotPair(b, a);
    }

    /** Whether the robot is one of the two. */
    public boolean contains(String robot) {
        return first.equals(robot) || second.equals(robot);
    }

    @Override
    public String toString() {
        return first + " <-> " + second;
    }
}
