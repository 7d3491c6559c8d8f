package org.usarsim.wss.routes;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * What the log and the event log say of the robots and the base (docs/routes.md), once per
 * change, from one route table to the next: a robot cut off from the base ({@code CUT_OFF}); a
 * robot with a route to it again, or whose route to it has other hops (another path), or a rate
 * that moved by {@link #RATE_CHANGE} or more of the last said one ({@code ROUTE}). A robot is said
 * when first seen, and again after it left and came back; a new base says every robot again.
 * Pure: the tables come in.
 */
public final class BaseWatch {

    /** A rate that moved less than this share of the last said one is not said again. */
    public static final double RATE_CHANGE = 0.10;

    /** One line: the robot and its route to the base ({@link Route#exists()} false: cut off). */
    public record Change(String robot, Route route) {
        public boolean cutOff() {
            return !route.exists();
        }
    }

    private String base;
    /** What was last said of each robot here. */
    private final Map<String, Route> said = new HashMap<>();

    /** What changed since the last table. */
    public List<Change> next(RouteTable table) {
        if (!Objects.equals(base, table.base())) {
            base = table.base();
            said.clear();
        }
        List<Change> changes = new ArrayList<>();
        if (base == null) {
            return changes;
        }
        said.keySet().retainAll(table.robots());
        for (String robot : table.robots()) {
            if (robot.equals(base)) {
                continue;
            }
            Route now = table.toBase(robot);
            Route before = said.get(robot);
            if (before == null || worthSaying(before, now)) {
                said.put(robot, now);
                changes.add(new Change(robot, now));
            }
        }
        return changes;
    }

    private static boolean worthSaying(Route before, Route now) {
        if (before.exists() != now.exists()) {
            return true;
        }
        if (!now.exists()) {
            return false;
        }
        if (!before.path().equals(now.path())) {
            return true;
        }
        return Math.abs(now.rateBound() - before.rateBound()) >= RATE_CHANGE * before.rateBound() && now.rateBound() != before.rateBound();
    }
}
