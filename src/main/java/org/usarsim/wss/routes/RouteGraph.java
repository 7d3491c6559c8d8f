package org.usarsim.wss.routes;

import java.util.List;

/**
 * What routes are found over: the robots (registered now), the ways of the pairs that are up now
 * (a pair up both ways is two hops, one each way), the rule, and the base ({@code wss.route.base},
 * null for none).
 */
public record RouteGraph(List<String> robots, List<Hop> hops, RouteRule rule, String base) {

    public RouteGraph {
        robots = List.copyOf(robots);
        hops = List.copyOf(hops);
    }

    /** No robots. */
    public static RouteGraph empty(RouteRule rule, String base) {
        return new RouteGraph(List.of(), List.of(), rule, base);
    }
}
