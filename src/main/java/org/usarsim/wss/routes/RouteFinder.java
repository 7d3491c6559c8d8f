package org.usarsim.wss.routes;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Finds the best route ({@link RouteRule}) from a robot to every other over the hops of a
 * {@link RouteGraph}. Pure: no sockets, no threads, no clock.
 *
 * <p>With shared airtime a relay's bound depends on the hop into it and the hop out of it, so a
 * robot alone is not a state of the search: a state is a robot and the rate of the hop that
 * reached it (a robot has as many as the distinct rates of its hops in, a few steps of the rate
 * table). The search goes by hop count, layer by layer (1 hop, 2 hops, ...), so the fewest hops win
 * a tie of ranks; a label (a route's rank so far) never grows as the route goes on, and a state
 * keeps only a label larger than any it had with fewer hops, and larger than those of the same
 * robot reached by a faster hop (which can only do better from there): a route is extended only
 * while it can still beat something. A route never passes a robot twice. Ties of rank and hops:
 * the first met, robots taken in name order, so the same graph gives the same routes.
 */
public final class RouteFinder {

    private final RouteRule rule;
    private final String base;
    private final List<String> names;
    private final Map<String, Integer> index = new HashMap<>();
    /** The hops by their source robot, then destination; {@code outStart[i]..outStart[i+1]} leave robot i. */
    private final Hop[] hops;
    private final int[] hopTo;
    private final int[] hopState;
    private final int[] outStart;
    /** The states of robot i are {@code stateStart[i]..stateStart[i+1]}, by the rate of the hop in, ascending. */
    private final int[] stateStart;
    private final int[] stateNode;

    public RouteFinder(RouteGraph graph) {
        this.rule = graph.rule();
        this.base = graph.base();
        this.names = graph.robots().stream().distinct().sorted().toList();
        for (int i = 0; i < names.size(); i++) {
            index.put(names.get(i), i);
        }
        int n = names.size();
        List<long[]> usable = new ArrayList<>(); // {from x n + to, index in the graph's hops}
        List<Hop> given = graph.hops();
        for (int h = 0; h < given.size(); h++) {
            Integer from = index.get(given.get(h).from());
            Integer to = index.get(given.get(h).to());
            if (from != null && to != null && !from.equals(to)) {
                usable.add(new long[] {(long) from * n + to, h});
            }
        }
        usable.sort((a, b) -> Long.compare(a[0], b[0]));
        hops = new Hop[usable.size()];
        hopTo = new int[hops.length];
        outStart = new int[n + 1];
        for (int h = 0; h < hops.length; h++) {
            hops[h] = given.get((int) usable.get(h)[1]);
            hopTo[h] = (int) (usable.get(h)[0] % n);
            outStart[(int) (usable.get(h)[0] / n) + 1]++;
        }
        for (int i = 0; i < n; i++) {
            outStart[i + 1] += outStart[i];
        }
        // The distinct keys of the hops into each robot: their rates with shared airtime, one key otherwise.
        long[][] keys = new long[n][];
        long[][] in = new long[n][];
        int[] inCount = new int[n];
        for (int h = 0; h < hops.length; h++) {
            inCount[hopTo[h]]++;
        }
        for (int i = 0; i < n; i++) {
            in[i] = new long[inCount[i]];
            inCount[i] = 0;
        }
        for (int h = 0; h < hops.length; h++) {
            in[hopTo[h]][inCount[hopTo[h]]++] = keyOf(hops[h]);
        }
        stateStart = new int[n + 1];
        for (int i = 0; i < n; i++) {
            keys[i] = Arrays.stream(in[i]).distinct().sorted().toArray();
            stateStart[i + 1] = stateStart[i] + keys[i].length;
        }
        stateNode = new int[stateStart[n]];
        for (int i = 0; i < n; i++) {
            Arrays.fill(stateNode, stateStart[i], stateStart[i + 1], i);
        }
        hopState = new int[hops.length];
        for (int h = 0; h < hops.length; h++) {
            int to = hopTo[h];
            hopState[h] = stateStart[to] + Arrays.binarySearch(keys[to], keyOf(hops[h]));
        }
    }

    private long keyOf(Hop hop) {
        return rule == RouteRule.FASTEST_SHARED_AIRTIME ? hop.bitsPerSecond() : 0;
    }

    /** Every ordered pair's best route over the graph, each robot's found when first asked ({@link RouteTable}). */
    public static RouteTable table(RouteGraph graph) {
        return new RouteTable(graph);
    }

    /**
     * The best routes from every robot that can reach {@code target} to it, by source: one search
     * over the hops turned round (a route's rank and hops are the same either way: the same
     * consecutive hops), each route turned back.
     */
    public static List<Route> to(RouteGraph graph, String target) {
        RouteRule rule = graph.rule();
        List<Hop> turned = new ArrayList<>(graph.hops().size());
        Map<Hop, Hop> original = new HashMap<>();
        for (Hop hop : graph.hops()) {
            Hop back = new Hop(hop.to(), hop.from(), hop.strength(), hop.bitsPerSecond());
            turned.add(back);
            original.put(back, hop);
        }
        List<Route> routes = new ArrayList<>();
        for (Route back : new RouteFinder(new RouteGraph(graph.robots(), turned, rule, graph.base())).from(target)) {
            List<String> path = new ArrayList<>(back.path());
            Collections.reverse(path);
            List<Hop> legs = new ArrayList<>();
            for (int i = back.legs().size() - 1; i >= 0; i--) {
                legs.add(original.get(back.legs().get(i)));
            }
            routes.add(new Route(path.get(0), target, path, legs, rule.weakest(legs), rule.bound(legs)));
        }
        return routes;
    }

    /** The best routes from one robot to each other it can reach, by destination (none when it is not in the graph). */
    public List<Route> from(String source) {
        Integer s = index.get(source);
        return s == null ? List.of() : new Search(s).run();
    }

    /** One source's search: its labels by state, and the routes found as a tree of entries. */
    private final class Search {
        private final int source;
        private final double[] best = new double[stateNode.length];
        private final int[] bestEntry = new int[stateNode.length];
        private final int[] mark = new int[names.size()];
        private int stamp;
        private int[] entHop = new int[64];
        private int[] entPred = new int[64];
        private int[] entLayer = new int[64];
        private double[] entValue = new double[64];
        private int entries;

        Search(int source) {
            this.source = source;
            Arrays.fill(best, Double.NEGATIVE_INFINITY);
        }

        List<Route> run() {
            int[] frontier = new int[0];
            List<Integer> next = new ArrayList<>();
            for (int h = outStart[source]; h < outStart[source + 1]; h++) {
                offer(h, rule.first(hops[h]), -1, 1, next);
            }
            int layer = 1;
            while (!next.isEmpty()) {
                frontier = next.stream().mapToInt(Integer::intValue).toArray();
                next = new ArrayList<>();
                layer++;
                for (int e : frontier) {
                    expand(e, layer, next);
                }
            }
            return routes();
        }

        private void expand(int e, int layer, List<Integer> next) {
            int state = hopState[entHop[e]];
            if (dominated(state, entValue[e], entLayer[e], bestEntry[state] == e ? 1 : 0)) {
                return; // beaten with no more hops: by a faster hop into the same robot, or by a better route in its own layer
            }
            stamp++;
            mark[source] = stamp;
            for (int p = e; p >= 0; p = entPred[p]) {
                mark[hopTo[entHop[p]]] = stamp;
            }
            int at = hopTo[entHop[e]];
            long inRate = hops[entHop[e]].bitsPerSecond();
            double value = entValue[e];
            for (int h = outStart[at]; h < outStart[at + 1]; h++) {
                if (mark[hopTo[h]] != stamp) {
                    offer(h, Math.min(value, rule.relayed(inRate, hops[h])), e, layer, next);
                }
            }
        }

        /**
         * Whether a state of the same robot reached by a hop no slower (from {@code state + skip}
         * on) has a label no smaller with no more hops.
         */
        private boolean dominated(int state, double value, int layer, int skip) {
            int end = stateStart[stateNode[state] + 1];
            for (int other = state + skip; other < end; other++) {
                if (best[other] >= value && best[other] != Double.NEGATIVE_INFINITY && entLayer[bestEntry[other]] <= layer) {
                    return true;
                }
            }
            return false;
        }

        private void offer(int hop, double value, int pred, int layer, List<Integer> next) {
            int state = hopState[hop];
            if (dominated(state, value, layer, 0)) {
                return;
            }
            if (entries == entHop.length) {
                int size = entries * 2;
                entHop = Arrays.copyOf(entHop, size);
                entPred = Arrays.copyOf(entPred, size);
                entLayer = Arrays.copyOf(entLayer, size);
                entValue = Arrays.copyOf(entValue, size);
            }
            int e = entries++;
            entHop[e] = hop;
            entPred[e] = pred;
            entLayer[e] = layer;
            entValue[e] = value;
            next.add(e); // one improved again in this layer is skipped when its turn comes (expand)
            best[state] = value;
            bestEntry[state] = e;
        }

        private List<Route> routes() {
            List<Route> routes = new ArrayList<>();
            for (int to = 0; to < names.size(); to++) {
                int chosen = -1;
                for (int state = stateStart[to]; state < stateStart[to + 1]; state++) {
                    if (best[state] == Double.NEGATIVE_INFINITY) {
                        continue;
                    }
                    int e = bestEntry[state];
                    if (chosen < 0 || entValue[e] > entValue[chosen] || entValue[e] == entValue[chosen] && entLayer[e] < entLayer[chosen]) {
                        chosen = e;
                    }
                }
                if (to != source && chosen >= 0) {
                    routes.add(route(chosen));
                }
            }
            return routes;
        }

        private Route route(int e) {
            List<Hop> path = new ArrayList<>();
            for (int p = e; p >= 0; p = entPred[p]) {
                path.add(hops[entHop[p]]);
            }
            Collections.reverse(path);
            List<String> robots = new ArrayList<>();
            robots.add(names.get(source));
            path.forEach(hop -> robots.add(hop.to()));
            return new Route(names.get(source), robots.get(robots.size() - 1), robots, path, rule.weakest(path), rule.bound(path));
        }
    }
}
