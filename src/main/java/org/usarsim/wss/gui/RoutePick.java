package org.usarsim.wss.gui;

/**
 * The two robots picked on the map for a route (docs/gui.md, "A route on the map"): a click on a
 * robot picks the start, a click on another the end, a third click (or Escape: {@link #NONE})
 * clears. A click on the start again clears too. Immutable; {@code from} and {@code to} null
 * while not picked.
 */
record RoutePick(String from, String to) {

    static final RoutePick NONE = new RoutePick(null, null);

    /** The pick after a click on {@code robot}. */
    RoutePick click(String robot) {
        if (from == null) {
            return new RoutePick(robot, null);
        }
        if (to == null && !robot.equals(from)) {
            return new RoutePick(from, robot);
        }
        return NONE;
    }

    /** Both ends picked: the map draws the route between them. */
    boolean complete() {
        return from != null && to != null;
    }
}
