package org.usarsim.wss.monitor;

import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.Map;
import org.usarsim.wss.hub.HubSnapshot.LinkEntry;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.HubSnapshot.PortEntry;
import org.usarsim.wss.hub.core.UdpCounts;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.hub.MapLines.Line;
import org.usarsim.wss.monitor.Reading.ModelView;
import org.usarsim.wss.monitor.Reading.ReplayView;
import org.usarsim.wss.monitor.Reading.RobotView;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The one place the monitor's JSON is shaped (docs/monitor.md): the state object and each of its
 * entries, as maps and lists for {@code ros.Json.write}. A number not known (NaN) is null.
 */
final class StateJson {

    /** What does not change during a run: the server's version, addresses and shaping. */
    record Server(String version, String bindAddress, int controlPort, ShapingConfig shaping) {
    }

    private StateJson() {
    }

    /** The whole state: GET /api/state and the snapshot event. */
    static Map<String, Object> state(Reading reading, Server server, String run, String lastEventId, Instant time, boolean operator) {
        Map<String, Object> state = new LinkedHashMap<>();
        state.put("run", run);
        state.put("lastEventId", lastEventId);
        state.put("time", time.truncatedTo(java.time.temporal.ChronoUnit.MILLIS).toString());
        state.put("operator", operator);
        Map<String, Object> about = new LinkedHashMap<>();
        about.put("version", server.version());
        about.put("bindAddress", server.bindAddress());
        about.put("controlPort", server.controlPort());
        state.put("server", about);
        state.put("model", reading.model() == null ? null : model(reading.model()));
        state.put("shaping", shaping(server.shaping()));
        state.put("replay", reading.replay() == null ? null : replay(reading.replay()));
        state.put("robots", reading.robots().stream().map(StateJson::robot).toList());
        state.put("ports", reading.ports().stream().map(StateJson::port).toList());
        state.put("links", reading.links().stream().map(StateJson::link).toList());
        state.put("pairs", reading.pairs().stream().map(StateJson::pair).toList());
        state.put("lines", reading.lines().stream().map(StateJson::line).toList());
        state.put("routes", reading.routes().json()); // for any token: the viewers are people (docs/monitor.md)
        return state;
    }

    static Map<String, Object> shaping(ShapingConfig shaping) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("on", shaping.on());
        json.put("rates", shaping.rates().toString());
        json.put("delayMs", shaping.delayMs());
        json.put("airtime", shaping.airtime());
        json.put("queueMs", shaping.queueMs());
        json.put("loss", shaping.loss().toString());
        return json;
    }

    static Map<String, Object> model(ModelView model) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("name", model.name());
        json.put("settings", new LinkedHashMap<>(model.settings()));
        json.put("cutoff", number(model.cutoff()));
        json.put("walls", model.walls().stream().map(StateJson::wall).toList());
        return json;
    }

    private static Map<String, Object> wall(Wall wall) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("x1", number(wall.x1()));
        json.put("y1", number(wall.y1()));
        json.put("x2", number(wall.x2()));
        json.put("y2", number(wall.y2()));
        return json;
    }

    static Map<String, Object> replay(ReplayView replay) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("timeSeconds", number(replay.timeSeconds()));
        json.put("durationSeconds", number(replay.durationSeconds()));
        json.put("speed", number(replay.speed()));
        json.put("playing", replay.playing());
        json.put("pollSeconds", number(replay.pollSeconds()));
        return json;
    }

    static Map<String, Object> robot(RobotView robot) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("name", robot.name());
        json.put("address", robot.address());
        json.put("ports", robot.ports());
        json.put("airtime", number(robot.airtime()));
        Map<String, Object> position = null;
        if (robot.position() != null) {
            position = new LinkedHashMap<>();
            position.put("x", number(robot.position().x()));
            position.put("y", number(robot.position().y()));
            position.put("z", number(robot.position().z()));
        }
        json.put("position", position);
        json.put("range", number(robot.range()));
        json.put("outOfBattery", robot.outOfBattery());
        return json;
    }

    static Map<String, Object> port(PortEntry port) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("from", port.from());
        json.put("to", port.to());
        json.put("targetPort", port.targetPort());
        json.put("wssPort", port.wssPort());
        json.put("listening", port.listening());
        json.put("kind", port.kind().name());
        return json;
    }

    static Map<String, Object> link(LinkEntry link) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("from", link.from());
        json.put("to", link.to());
        json.put("targetPort", link.targetPort());
        json.put("wssPort", link.wssPort());
        json.put("outgoingPort", link.outgoingPort());
        return json;
    }

    static Map<String, Object> pair(PairEntry pair) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("first", pair.first());
        json.put("second", pair.second());
        json.put("state", pair.state().name());
        json.put("forced", pair.state().isForced());
        json.put("strength", number(pair.strength()));
        json.put("distance", number(pair.distance()));
        json.put("bytesFirstToSecond", pair.bytesFirstToSecond());
        json.put("bytesSecondToFirst", pair.bytesSecondToFirst());
        json.put("rateFirstToSecond", number(pair.rateFirstToSecond()));
        json.put("rateSecondToFirst", number(pair.rateSecondToFirst()));
        json.put("connections", pair.connections());
        json.put("breaks", pair.breaks());
        json.put("resumes", pair.resumes());
        json.put("upShare", number(pair.upShare()));
        json.put("lastClose", pair.lastClose());
        json.put("linkRateFirstToSecond", pair.linkRateFirstToSecond());
        json.put("linkRateSecondToFirst", pair.linkRateSecondToFirst());
        json.put("udpFirstToSecond", udp(pair.udpFirstToSecond()));
        json.put("udpSecondToFirst", udp(pair.udpSecondToFirst()));
        return json;
    }

    private static Map<String, Object> udp(UdpCounts.Reading udp) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("datagrams", udp.datagrams());
        json.put("bytes", udp.bytes());
        json.put("droppedBroken", udp.droppedBroken());
        json.put("droppedQueue", udp.droppedQueue());
        json.put("lost", udp.lost());
        return json;
    }

    static Map<String, Object> line(Line line) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("first", line.first());
        json.put("second", line.second());
        json.put("state", line.state().name());
        json.put("strength", number(line.strength()));
        json.put("rate", line.rate());
        return json;
    }

    /** A pair's or line's key in a removal. */
    static Map<String, Object> pairKey(String first, String second) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("first", first);
        json.put("second", second);
        return json;
    }

    /** A port's key in a removal. */
    static Map<String, Object> portKey(PortEntry port) {
        Map<String, Object> json = port(port);
        json.remove("listening");
        json.remove("kind");
        return json;
    }

    /** NaN and infinities are null: JSON has no such numbers. */
    static Double number(double value) {
        return Double.isFinite(value) ? value : null;
    }

    /** A short JSON error body. */
    static Map<String, Object> error(String text) {
        return Map.of("error", text);
    }
}
