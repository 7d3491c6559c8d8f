package org.usarsim.wss.routes;

import java.util.List;

/**
 * The best route from one robot to another ({@link RouteRule}): the robots in order, the source
 * first and the destination last (empty when there is none); its hops in order, each with its
 * strength and rate ({@code legs}: {@code path.size() - 1} of them); its weakest hop (the slowest with
 * links shaped, the weakest in dBm without; null when there is no route); with links shaped, the
 * rate one stream could have over the whole route (bit/s; 0 unshaped or no route).
 */
public record Route(String from, String to, List<String> path, List<Hop> legs, Hop weakest, long rateBound) {

    public Route {
        path = List.copyOf(path);
        legs = List.copyOf(legs);
    }

    /** No route from one to the other. */
    public static Route none(String from, String to) {
        return new Route(from, to, List.of(), List.of(), null, 0);
    }

    /** Whether there is a route. */
    public boolean exists() {
        return !path.isEmpty();
    }

    /** Its hops: 1 for a direct link, -1 when there is no route. */
    public int hops() {
        return path.size() - 1;
    }

    /** The path as the wire and the CSV say it: {@code A,R1,B} (empty when there is none). */
    public String pathText() {
        return String.join(",", path);
    }
}
