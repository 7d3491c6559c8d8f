package org.usarsim.wss.routes;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Every ordered pair's best route over one {@link RouteGraph} ({@link RouteFinder#table}), with the
 * rule it was found by and the base robots are cut off from. Immutable, and found lazily: a
 * robot's routes are searched when first asked (one search, about 1/N of the whole table), every
 * robot's route to the base by one search from the base; safe on any thread. Two tables are
 * equal when their graphs are (the same robots, hops, rule and base: the same routes).
 */
public final class RouteTable {

    /** No robots, no routes, no base. */
    public static final RouteTable EMPTY = RouteFinder.table(RouteGraph.empty(RouteRule.STRONGEST, null));

    private final RouteRule rule;
    private final String base;
    private final List<String> robots;
    private final Set<Hop> hops;
    private final RouteGraph graph;
    /** Made when a robot's routes are first asked (the routes to the base need none). */
    private RouteFinder finder;
    /** From, to: the routes found so far (those that exist). */
    private final Map<String, Map<String, Route>> found = new ConcurrentHashMap<>();
    /** Each robot's route to the base, once asked. */
    private volatile Map<String, Route> toBase;

    RouteTable(RouteGraph graph) {
        this.graph = graph;
        this.rule = graph.rule();
        this.base = graph.base();
        this.robots = graph.robots().stream().distinct().sorted().toList();
        this.hops = Set.copyOf(graph.hops());
    }

    /**
     * A table whose routes were found elsewhere (a monitor's state, read by an attached window:
     * docs/monitor.md): the routes that exist as given, every other pair none; nothing is searched.
     */
    public static RouteTable known(RouteRule rule, String base, List<String> robots, List<Route> routes) {
        java.util.Set<Hop> legs = new java.util.LinkedHashSet<>();
        routes.forEach(route -> legs.addAll(route.legs()));
        RouteTable table = new RouteTable(new RouteGraph(robots, List.copyOf(legs), rule, base));
        table.robots.forEach(robot -> table.found.put(robot, new HashMap<>()));
        Map<String, Route> toBase = new HashMap<>();
        for (Route route : routes) {
            if (table.found.containsKey(route.from()) && route.exists()) {
                table.found.get(route.from()).put(route.to(), route);
                if (route.to().equals(base)) {
                    toBase.put(route.from(), route);
                }
            }
        }
        table.toBase = Map.copyOf(toBase);
        return table;
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

    /**
     * The best route from one robot to another: {@link Route#none} when there is none (or either
     * is not here). A route to the base is the one {@link #toBase} gives.
     */
    public Route route(String from, String to) {
        Route route = to.equals(base) ? toBaseRoutes().get(from) : routesFrom(from).get(to);
        return route == null || from.equals(to) ? Route.none(from, to) : route;
    }

    private Map<String, Route> routesFrom(String from) {
        if (!robots.contains(from)) {
            return Map.of();
        }
        return found.computeIfAbsent(from, robot -> {
            Map<String, Route> to = new HashMap<>();
            finder().from(robot).forEach(route -> to.put(route.to(), route));
            return to;
        });
    }

    private synchronized RouteFinder finder() {
        if (finder == null) {
            finder = new RouteFinder(graph);
        }
        return finder;
    }

    private Map<String, Route> toBaseRoutes() {
        Map<String, Route> routes = toBase;
        if (routes == null) {
            Map<String, Route> by = new HashMap<>();
            if (base != null) {
                RouteFinder.to(graph, base).forEach(route -> by.put(route.from(), route));
            }
            routes = Map.copyOf(by);
            toBase = routes;
        }
        return routes;
    }

    /** Every ordered pair of robots' route, those without one too, by from then to (every robot's search: not on the event thread). */
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
            Route route = route(robot, to);
            if (route.exists()) {
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
        return base != null && !base.equals(robot) && !toBase(robot).exists();
    }

    /** The robots cut off from the base, by name (none without a base). */
    public List<String> cutOff() {
        return robots.stream().filter(this::isCutOff).toList();
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof RouteTable table && rule == table.rule && Objects.equals(base, table.base)
                && robots.equals(table.robots) && hops.equals(table.hops);
    }

    @Override
    public int hashCode() {
        return Objects.hash(rule, base, robots, hops);
    }

    @Override
    public String toString() {
        return "RouteTable" + robots + " " + hops;
    }
}
