package org.usarsim.wss.model;

import java.util.List;

/**
 * What one poll of a simulator model learned and decided, as a recording keeps it
 * (docs/replay.md): every robot the simulator listed, where and whether its battery is empty; the
 * robots it kicked and why; every pair of present robots with its strength, obstacle count and
 * link state as decided; the simulator's walls. Models without a simulator never send one.
 */
public record ModelPoll(List<Robot> robots, List<Kick> kicks, List<Pair> pairs, List<Wall> walls) {

    public ModelPoll {
        robots = List.copyOf(robots);
        kicks = List.copyOf(kicks);
        pairs = List.copyOf(pairs);
        walls = List.copyOf(walls);
    }

    /** A robot as the simulator listed it. */
    public record Robot(String name, Position position, boolean batteryEmpty) {
    }

    /** A registered robot the poll kicked: its battery is empty, or the simulator does not list it. */
    public record Kick(String robot, boolean batteryEmpty) {
    }

    /**
     * A pair of present robots (names as {@link RobotPair} orders them): the strength between them in
     * dBm (the simulator models' strength is the same both ways), the obstacles counted between them
     * (NaN: not counted) and whether the link is up, as this poll decided.
     */
    public record Pair(String first, String second, double strength, double obstacles, boolean live) {
    }
}
