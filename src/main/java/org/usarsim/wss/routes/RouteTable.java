package org.usarsim.wss.routes;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * Every ordered pair's best route at one instant ({@link RouteFinder#table}), with the rule it was
 * found by and the base robots are cut off from. Immutable; equal when the routes are.
 */
public final class RouteTable {

    /** No robots, no routes, no base. */
    public static final RouteTable EMPTY = new RouteTable(RouteRule.STRONGEST, null, List.of(), Map.of());

    private final RouteRule rule;
    private final String base;
    private final List<String> robots;
    /** From, to: the route (only those that exist). */
    private final Map<String, Map<String, Route>> routes;

    RouteTable(RouteRule rule, String base, List<String> robots, Map<String, Map<String, Route>> routes) {
        this.rule = rule;
        this.base = base;
        this.robots = List.copyOf(robots);
        Map<String, Map<String, Route>> copy = new HashMap<>();
        routes.forEach((from, to) -> copy.put(from, Map.copyOf(to)));
        this.routes = Map.copyOf(copy);
    }

    /** The rule the routes were found by (whether they have rates). */
    public RouteRule rule() {
        return rule;
    }

    /** The base ({@code wss.route.base}), null when there is none. */
    public String base() {
        return base;
    }

    /** The robots, by name. */
    public List<String> robots() {
        return robots;
    }

    /** The best route from one robot to another: {@link Route#none} when there is none (or either is not here). */
    public Route route(String from, String to) {
        Route route = routes.getOrDefault(from, Map.of()).get(to);
        return route == null ? Route.none(from, to) : route;
    }

    /** Every ordered pair of robots' route, those without one too, by from then to. */
    public List<Route> all() {
        List<Route> all = new ArrayList<>();
        for (String from : robots) {
            for (String to : robots) {
                if (!from.equals(to)) {
                    all.add(route(from, to));
                }
            }
        }
        return all;
    }

    /** The routes from one robot that exist, by destination. */
    public List<Route> from(String robot) {
        List<Route> from = new ArrayList<>();
        for (String to : robots) {
            Route route = routes.getOrDefault(robot, Map.of()).get(to);
            if (route != null) {
                from.add(route);
            }
        }
        return from;
    }

    /** The robot's route to the base ({@link Route#none} without a base). */
    public Route toBase(String robot) {
        return base == null ? Route.none(robot, robot) : route(robot, base);
    }

    /** Whether the robot is cut off: there is a base, it is not the robot, and the robot has no route to it. */
    public boolean isCutOff(String robot) {
        return base != null && !base.equals(robot) && !route(robot, base).exists();
    }

    /** The robots cut off from the base, by name (none without a base). */
    public List<String> cutOff() {
        return robots.stream().filter(this::isCutOff).toList();
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof RouteTable table && rule == table.rule && Objects.equals(base, table.base)
                && robots.equals(table.robots) && routes.equals(table.routes);
    }

    @Override
    public int hashCode() {
        return Objects.hash(rule, base, robots, routes);
    }

    @Override
    public String toString() {
        return "RouteTable" + all();
    }
}
