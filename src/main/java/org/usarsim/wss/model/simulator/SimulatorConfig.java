package org.usarsim.wss.model.simulator;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.ModelSettings;

/**
 * A simulator model's configuration for one run, read and checked once at its start: every value
 * by its declared {@link Setting}'s rule (the defaults and the rules are written only there), then
 * frozen. {@link #values} holds every declared key, for what a subclass declares besides;
 * {@link #rosbridge} the rosbridge settings when the positions come from rosbridge, else null.
 */
record SimulatorConfig(String host, int port, int intervalMs, int timeoutMs, PathLoss pathLoss, double margin,
        double holdSeconds, ModelSettings values, RosbridgeConfig rosbridge) {

    /** The values given over the declared defaults, each checked; the first refused one stops the start. */
    static SimulatorConfig read(List<Setting> declared, Map<String, String> given) throws ModelStartException {
        Map<String, Setting> rules = new LinkedHashMap<>();
        SimulatorSettings.ALL.forEach(setting -> rules.put(setting.key(), setting));
        declared.forEach(setting -> rules.put(setting.key(), setting));
        Map<String, String> values;
        try {
            values = Setting.checked(rules.values(), given);
        } catch (IllegalArgumentException e) {
            throw new ModelStartException(e.getMessage());
        }
        ModelSettings checked = new ModelSettings(values);
        int intervalMs = checked.getInt("positions.interval", 0);
        RosbridgeConfig rosbridge = SimulatorModel.ROSBRIDGE.equals(checked.getString("positions", null))
                ? RosbridgeConfig.read(checked, intervalMs) : null;
        return new SimulatorConfig(checked.getString("usarsim.host", null), checked.getInt("usarsim.port", 0),
                intervalMs, checked.getInt("usarsim.timeout", 0),
                new PathLoss(checked.getDouble("distance.pd0", 0), checked.getDouble("distance.n", 0),
                        checked.getDouble("distance.d0", 0), checked.getDouble("distance.cutoff", 0)),
                checked.getDouble("distance.margin", 0), checked.getDouble("distance.holdTime", 0), checked, rosbridge);
    }

    /** How the run opens its source of positions, the one {@code positions} names. */
    PositionSource.Opener opener(PollClock clock) {
        return rosbridge != null ? RosbridgeSource.opener(rosbridge, clock) : UsarsimSource.opener(host, port, timeoutMs);
    }

    /** Where the positions come from, as the log says it: host:port, or the rosbridge URL and topic. */
    String where() {
        return rosbridge != null ? rosbridge.where() : host + ":" + port;
    }
}
