package org.usarsim.wss.hub;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.routes.Hop;
import org.usarsim.wss.routes.RouteGraph;
import org.usarsim.wss.routes.RouteRule;
import org.usarsim.wss.shaping.RateTable;

/**
 * What routes are found over, from a {@link HubSnapshot}: its registered robots, and both ways of
 * every pair whose state lets it talk now (up by the model or forced up; {@code PairState.isUp}),
 * each with the model's strength and, with links shaped, the pair's rate that way. A pair of
 * registered robots the hub has not seen yet (no poll decided it, no link, no force: every pair
 * under a model that never breaks one, such as the Noop model) is up as the map draws it
 * ({@link MapLines#unseen}), with the model's strength and, shaped, the rate the rate table gives
 * that strength (what its first link would get).
 */
public final class RouteGraphs {

    private RouteGraphs() {
    }

    /** Over the pairs the hub has seen only. */
    public static RouteGraph of(HubSnapshot snapshot, RouteRule rule, String base) {
        return of(snapshot, rule, base, null, null);
    }

    /** {@code model} null: the pairs the hub has seen only; {@code rates} null: not shaped. */
    public static RouteGraph of(HubSnapshot snapshot, RouteRule rule, String base, PropagationModel model, RateTable rates) {
        List<String> robots = snapshot.robots().stream().map(HubSnapshot.RobotEntry::name).toList();
        List<Hop> hops = new ArrayList<>();
        Set<String> seen = new HashSet<>();
        for (HubSnapshot.PairEntry pair : snapshot.pairs()) {
            seen.add(pair.first() + '\n' + pair.second());
            seen.add(pair.second() + '\n' + pair.first());
            if (pair.state().isUp()) {
                hops.add(new Hop(pair.first(), pair.second(), pair.strength(), pair.linkRateFirstToSecond()));
                hops.add(new Hop(pair.second(), pair.first(), pair.strength(), pair.linkRateSecondToFirst()));
            }
        }
        if (model != null) {
            for (int i = 0; i < robots.size(); i++) {
                for (int j = i + 1; j < robots.size(); j++) {
                    String a = robots.get(i);
                    String b = robots.get(j);
                    if (!seen.contains(a + '\n' + b) && MapLines.unseen(model, a, b).isUp()) {
                        double strength = model.getSignalStrengthForPair(a, b);
                        long rate = rates == null ? 0 : rates.rateFor(strength);
                        hops.add(new Hop(a, b, strength, rate));
                        hops.add(new Hop(b, a, strength, rate));
                    }
                }
            }
        }
        return new RouteGraph(robots, hops, rule, base);
    }
}
