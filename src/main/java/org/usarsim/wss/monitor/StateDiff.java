package org.usarsim.wss.monitor;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Function;
import org.usarsim.wss.hub.HubSnapshot.LinkEntry;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.HubSnapshot.PortEntry;
import org.usarsim.wss.hub.MapLines.Line;
import org.usarsim.wss.monitor.Reading.ReplayView;
import org.usarsim.wss.monitor.Reading.RobotView;

/**
 * What changed between the state the streams were last told ({@link #sent}) and a new reading, as
 * the events that tell it (docs/monitor.md, "GET /api/events"): a change of structure at once, a
 * change of counts only (bytes, rates, strengths, positions, the replay's time) only when
 * {@code countsDue}; the changes of one kind in one event; the routes, when their table changed, with the counts (at once when a robot is cut off or back), as the routes that changed (or whole, when that is shorter or the base, rule or shaping changed). Pure: one thread (the publisher's).
 */
final class StateDiff {

    /** An event to publish: its type and its data (maps and lists for ros.Json). */
    record Change(String type, Object data) {
    }

    private Reading sent = Reading.EMPTY;

    /** The state the events so far told: what a new stream's snapshot shows. */
    Reading sent() {
        return sent;
    }

    /** Forgets what was told: the next step tells nothing and takes the reading as told (a stream's snapshot tells it). */
    void reset(Reading now) {
        sent = now;
    }

    List<Change> step(Reading now, boolean countsDue) {
        List<Change> changes = new ArrayList<>();
        Map<String, Object> removed = new LinkedHashMap<>();
        List<RobotView> robots = kind(sent.robots(), now.robots(), RobotView::name,
                r -> new RobotView(r.name(), r.address(), r.ports(), 0, null, 0, r.outOfBattery()), countsDue, "robots",
                StateJson::robot, RobotView::name, changes, removed);
        List<PortEntry> ports = kind(sent.ports(), now.ports(), StateDiff::portKey, p -> p, countsDue, "ports", StateJson::port,
                StateJson::portKey, changes, removed);
        List<LinkEntry> links = kind(sent.links(), now.links(), l -> l, l -> l, countsDue, "links", StateJson::link, StateJson::link,
                changes, removed);
        List<PairEntry> pairs = kind(sent.pairs(), now.pairs(), p -> p.first() + '\n' + p.second(), StateDiff::pairStructure, countsDue,
                "pairs", StateJson::pair, p -> StateJson.pairKey(p.first(), p.second()), changes, removed);
        List<Line> lines = kind(sent.lines(), now.lines(), l -> l.first() + '\n' + l.second(),
                l -> new Line(l.first(), l.second(), l.state(), 0, l.rate()), countsDue, "lines", StateJson::line,
                l -> StateJson.pairKey(l.first(), l.second()), changes, removed);
        Reading.ModelView model = sent.model();
        if (!Objects.equals(model, now.model())) {
            model = now.model();
            changes.add(new Change("model", model == null ? null : StateJson.model(model)));
        }
        ReplayView replay = sent.replay();
        if (!Objects.equals(replay, now.replay()) && (countsDue || !Objects.equals(replayStructure(replay), replayStructure(now.replay())))) {
            replay = now.replay();
            changes.add(new Change("replay", replay == null ? null : StateJson.replay(replay)));
        }
        RoutesJson routes = sent.routes();
        boolean cutOffChanged = !routes.json().get("cutOff").equals(now.routes().json().get("cutOff"));
        if (routes != now.routes() && (countsDue || cutOffChanged) && !routes.table().equals(now.routes().table())) {
            Map<String, Object> routeChanges = now.routes().changesFrom(routes);
            if (routeChanges == null) {
                changes.add(new Change("routes", now.routes().json()));
            } else if (!((List<?>) routeChanges.get("routes")).isEmpty() || !((List<?>) routeChanges.get("gone")).isEmpty()
                    || !routeChanges.get("cutOff").equals(routes.json().get("cutOff"))) {
                changes.add(new Change("routeChanges", routeChanges));
            }
            routes = now.routes();
        }
        if (!removed.isEmpty()) {
            changes.add(new Change("removed", removed));
        }
        sent = new Reading(robots, ports, links, pairs, lines, model, replay, routes);
        return changes;
    }

    /**
     * One kind of entry: the entries of {@code now} that are new, or changed in structure (or at all
     * when counts are due), become one event; those gone, one list of {@code removed}. Returns what
     * is told now: {@code now}'s entries in its order, the old one kept where a change of counts waits.
     */
    private static <T> List<T> kind(List<T> before, List<T> now, Function<T, Object> key, Function<T, Object> structure, boolean countsDue,
            String type, Function<T, Map<String, Object>> json, Function<T, Object> removal, List<Change> changes,
            Map<String, Object> removed) {
        Map<Object, T> old = new LinkedHashMap<>();
        for (T entry : before) {
            old.put(key.apply(entry), entry);
        }
        List<T> told = new ArrayList<>(now.size());
        List<Map<String, Object>> changed = new ArrayList<>();
        for (T entry : now) {
            T was = old.remove(key.apply(entry));
            if (was == null || (!was.equals(entry) && (countsDue || !structure.apply(was).equals(structure.apply(entry))))) {
                changed.add(json.apply(entry));
                told.add(entry);
            } else {
                told.add(was);
            }
        }
        if (!changed.isEmpty()) {
            changes.add(new Change(type, changed));
        }
        if (!old.isEmpty()) {
            removed.put(type, old.values().stream().map(removal).toList());
        }
        return told;
    }

    private static Object portKey(PortEntry port) {
        return List.of(port.from(), port.to(), port.targetPort(), port.wssPort());
    }

    /** What of a pair is structure: its state, connections, breaks and resumes, why it last closed, its link rates. */
    private static Object pairStructure(PairEntry p) {
        return List.of(p.state(), p.connections(), p.breaks(), p.resumes(), Objects.toString(p.lastClose()), p.linkRateFirstToSecond(),
                p.linkRateSecondToFirst());
    }

    private static Object replayStructure(ReplayView replay) {
        return replay == null ? List.of() : List.of(replay.durationSeconds(), replay.speed(), replay.playing());
    }
}
