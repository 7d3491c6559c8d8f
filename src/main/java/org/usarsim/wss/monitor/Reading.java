package org.usarsim.wss.monitor;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.HubSnapshot.LinkEntry;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.HubSnapshot.PortEntry;
import org.usarsim.wss.hub.MapLines;
import org.usarsim.wss.hub.MapLines.Line;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.Wall;

/**
 * What the monitor shows at one instant (docs/monitor.md, "GET /api/state"): the hub's snapshot,
 * each robot with what the map needs of the model, the map's lines, the model, the replay and the
 * routes (as the publisher last made them: {@link RoutesJson}).
 * Taken off the hub's threads; never changed after.
 */
record Reading(List<RobotView> robots, List<PortEntry> ports, List<LinkEntry> links, List<PairEntry> pairs, List<Line> lines,
        ModelView model, ReplayView replay, RoutesJson routes) {

    static final Reading EMPTY = new Reading(List.of(), List.of(), List.of(), List.of(), List.of(), null, null, RoutesJson.EMPTY);

    /** A registered robot as the hub and the model know it; {@code position} null and {@code range} NaN when the model has none. */
    record RobotView(String name, String address, List<Integer> ports, double airtime, Position position, double range, boolean outOfBattery) {
    }

    /** The run's model: its name, the run's values of its settings, its cutoff (NaN: none) and walls. */
    record ModelView(String name, Map<String, String> settings, double cutoff, List<Wall> walls) {
    }

    /** Where the replay is (seconds), how fast, whether it plays. */
    record ReplayView(double timeSeconds, double durationSeconds, double speed, boolean playing, double pollSeconds) {

        static ReplayView of(Optional<Replay> replay) {
            return replay.map(r -> new ReplayView(r.timeSeconds(), r.durationSeconds(), r.speed(), r.playing(), r.pollSeconds())).orElse(null);
        }
    }

    /**
     * The hub's snapshot with the model's answers: positions and ranges, and the map's lines
     * ({@link MapLines}, the window's rule).
     */
    static Reading of(HubSnapshot hub, PropagationModel model, Map<String, String> settings, Set<String> outOfBattery, RoutesJson routes) {
        List<RobotView> robots = new ArrayList<>();
        for (HubSnapshot.RobotEntry entry : hub.robots()) {
            String name = entry.name();
            robots.add(new RobotView(name, entry.address(), entry.ports(), entry.airtime(), model.positionOf(name).orElse(null),
                    model.rangeFor(name, name), outOfBattery.contains(name)));
        }
        List<Line> lines = MapLines.of(robots.stream().map(RobotView::name).toList(), hub, model);
        ModelView view = new ModelView(model.name(), settings, model.cutoff(), model.walls());
        return new Reading(robots, hub.ports(), hub.links(), hub.pairs(), lines, view, ReplayView.of(model.replay()), routes);
    }
}
