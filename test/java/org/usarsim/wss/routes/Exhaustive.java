package org.usarsim.wss.routes;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/** Every simple path tried: the best rank and its fewest hops, the test's reference. */
final class Exhaustive {

    private Exhaustive() {
    }

    /** {rank, hops}: hops -1 when there is no path. */
    static long[] best(RouteRule rule, List<Hop> hops, String from, String to) {
        long[] best = {Long.MIN_VALUE, -1};
        Set<String> visited = new HashSet<>();
        visited.add(from);
        walk(rule, hops, from, to, new ArrayList<>(), visited, best);
        return best;
    }

    /** The hops along a path of robots (a hop missing fails the test). */
    static List<Hop> hopsOf(List<String> path, List<Hop> hops) {
        List<Hop> along = new ArrayList<>();
        for (int i = 1; i < path.size(); i++) {
            String from = path.get(i - 1);
            String to = path.get(i);
            along.add(hops.stream().filter(hop -> hop.from().equals(from) && hop.to().equals(to)).findFirst().orElseThrow());
        }
        return along;
    }

    private static void walk(RouteRule rule, List<Hop> hops, String at, String to, List<Hop> path, Set<String> visited, long[] best) {
        if (at.equals(to)) {
            long rank = rule.shaped() ? rule.bound(path) : (long) rule.weakest(path).strength();
            if (rank > best[0] || rank == best[0] && path.size() < best[1]) {
                best[0] = rank;
                best[1] = path.size();
            }
            return;
        }
        for (Hop hop : hops) {
            if (hop.from().equals(at) && visited.add(hop.to())) {
                path.add(hop);
                walk(rule, hops, hop.to(), to, path, visited, best);
                path.remove(path.size() - 1);
                visited.remove(hop.to());
            }
        }
    }
}
