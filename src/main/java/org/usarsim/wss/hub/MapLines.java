package org.usarsim.wss.hub;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.model.PropagationModel;

/**
 * The map's lines, one rule for the window's map ({@code gui.MapData}) and the monitor's
 * ({@code monitor.Reading}): a line for every pair of the given robots, in the state the hub's pair
 * gives it (forced ones included) with its link rate, or, for a pair the hub has not seen yet, up
 * or broken as the model allows (no rate); the strength the model's now. Asks only the model's
 * query methods (never the hub's lock).
 */
public final class MapLines {

    /** A pair of robots (names in the order given), its state, the model's strength (dBm, NaN unknown), its link rate ({@link #rateOf}). */
    public record Line(String first, String second, PairState state, double strength, long rate) {
    }

    private MapLines() {
    }

    /** The lines of every pair of {@code robots} (registered, in the snapshot's order: by name). */
    public static List<Line> of(List<String> robots, HubSnapshot hub, PropagationModel model) {
        Map<String, HubSnapshot.PairEntry> seen = new HashMap<>();
        for (HubSnapshot.PairEntry pair : hub.pairs()) {
            seen.put(pair.first() + '\n' + pair.second(), pair);
        }
        List<Line> lines = new ArrayList<>();
        for (int i = 0; i < robots.size(); i++) {
            for (int j = i + 1; j < robots.size(); j++) {
                String a = robots.get(i);
                String b = robots.get(j);
                HubSnapshot.PairEntry pair = seen.get(a + '\n' + b);
                PairState state = pair != null ? pair.state() : unseen(model, a, b);
                lines.add(new Line(a, b, state, model.getSignalStrengthForPair(a, b), pair == null ? 0 : rateOf(pair)));
            }
        }
        return lines;
    }

    /** The state of a pair the hub has not seen yet (no poll decided it, no link, no force): up or broken as the model allows. */
    static PairState unseen(PropagationModel model, String a, String b) {
        return model.connectionIsPossibleForPair(a, b) ? PairState.UP : PairState.BROKEN;
    }

    /** A pair's link rate for the map: the slower way's (bit/s), or the one known; 0 with links not shaped. */
    public static long rateOf(HubSnapshot.PairEntry pair) {
        long one = pair.linkRateFirstToSecond();
        long other = pair.linkRateSecondToFirst();
        return one > 0 && other > 0 ? Math.min(one, other) : Math.max(one, other);
    }
}
