package org.usarsim.wss.hub;

import java.util.ArrayList;
import java.util.List;
import org.usarsim.wss.routes.Hop;
import org.usarsim.wss.routes.RouteGraph;
import org.usarsim.wss.routes.RouteRule;

/**
 * What routes are found over, from a {@link HubSnapshot}: its registered robots, and both ways of
 * every pair whose state lets it talk now (up by the model or forced up; {@code PairState.isUp}),
 * each with the model's strength and, with links shaped, the pair's rate that way.
 */
public final class RouteGraphs {

    private RouteGraphs() {
    }

    public static RouteGraph of(HubSnapshot snapshot, RouteRule rule, String base) {
        List<String> robots = snapshot.robots().stream().map(HubSnapshot.RobotEntry::name).toList();
        List<Hop> hops = new ArrayList<>();
        for (HubSnapshot.PairEntry pair : snapshot.pairs()) {
            if (pair.state().isUp()) {
                hops.add(new Hop(pair.first(), pair.second(), pair.strength(), pair.linkRateFirstToSecond()));
                hops.add(new Hop(pair.second(), pair.first(), pair.strength(), pair.linkRateSecondToFirst()));
            }
        }
        return new RouteGraph(robots, hops, rule, base);
    }
}
