package org.usarsim.wss.app;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import org.usarsim.wss.hub.FixedSetup;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.shaping.LossTable;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The hub's configuration ({@link HubConfig}) built from a run's {@code wss.*} values, each checked
 * by its own rule before, and the checks its parts need together: the forced pairs, the link
 * shaping, the declared robots with the fixed ports, and whether those ports are free.
 * {@link ConfigFile} asks each check as it reads a file (a {@link ConfigFileException} naming the
 * file), then builds with it.
 */
final class HubConfigBuilder {

    private final Map<String, String> values;

    /** A builder over these values, by key (the configuration's own map, read as it is). */
    HubConfigBuilder(Map<String, String> values) {
        this.values = values;
    }

    private String get(String key) {
        return values.get(key);
    }

    /** The hub's configuration, of values {@link ConfigFile} checked with this builder. */
    HubConfig build() {
        try {
            return new HubConfig(InetAddress.getByName(get("wss.bindAddress")), Integer.parseInt(get("wss.port")),
                    Integer.parseInt(get("wss.chunkSize")), Integer.parseInt(get("wss.socketBuffer")),
                    Boolean.parseBoolean(get("wss.matchSourceAddress")), Integer.parseInt(get("wss.portMemory")),
                    Integer.parseInt(get("wss.maxPortsPerRobot")), Integer.parseInt(get("wss.maxPortsPerAddress")),
                    Integer.parseInt(get("wss.deadPeerSeconds")), Set.copyOf(listed(get("wss.operators"), Setting::addressList)),
                    forcedPairs(null), ForcedUp.parse(get("wss.force.up")).pins(), shaping(null), fixed(null));
        } catch (UnknownHostException | ConfigFileException e) {
            throw new IllegalStateException("wss.bindAddress, wss.operators, wss.force.*, wss.shaping.*, wss.robot.* and wss.fixed were checked", e);
        }
    }

    /** The shaping settings, checked together (docs/shaping.md). */
    ShapingConfig shaping(String source) throws ConfigFileException {
        Map<String, String> shapingValues = new LinkedHashMap<>();
        for (String key : ConfigKeys.SHAPING_KEYS) {
            shapingValues.put(key, get(key));
        }
        try {
            RateTable.parse(get(ShapingConfig.RATES));
        } catch (IllegalArgumentException e) {
            throw new ConfigFileException(source + ": " + ShapingConfig.RATES + " = '" + get(ShapingConfig.RATES) + "' is not "
                    + ConfigKeys.RATES_WORDS + ": " + e.getMessage());
        }
        shapingValues.put(ShapingConfig.LOSS, get(ShapingConfig.LOSS));
        shapingValues.put(ShapingConfig.SEED, get(ShapingConfig.SEED));
        try {
            Long.parseLong(get(ShapingConfig.SEED).strip());
        } catch (NumberFormatException e) {
            throw new ConfigFileException(source + ": " + ShapingConfig.SEED + " = '" + get(ShapingConfig.SEED) + "' is not a whole number"
                    + " (from " + Long.MIN_VALUE + " to " + Long.MAX_VALUE + ")");
        }
        try {
            LossTable.parse(get(ShapingConfig.LOSS));
        } catch (IllegalArgumentException e) {
            throw new ConfigFileException(source + ": " + ShapingConfig.LOSS + " = '" + get(ShapingConfig.LOSS) + "' is not "
                    + ConfigKeys.LOSS_WORDS + ": " + e.getMessage());
        }
        try {
            return ShapingConfig.from(shapingValues);
        } catch (IllegalArgumentException e) {
            throw new ConfigFileException(source + ": " + e.getMessage());
        }
    }

    /**
     * Refuses a fixed port whose number something on this machine holds now: checked as the file
     * is read, and again as the window's Start starts a server (the number may have been taken since).
     *
     * @throws IllegalArgumentException {@code wss.fixed = '...' is not ...: tcp A->B:1883@11883: tcp port 11883 is in use (why)}
     */
    void checkFixedPortsFree() {
        HubConfig hub = build();
        FixedPorts.checkFree(hub.fixed(), get(FixedPorts.KEY), hub.bindAddress());
    }

    /** The declared robots and the fixed ports, checked together (docs/fixed-ports.md). */
    FixedSetup fixed(String source) throws ConfigFileException {
        Map<String, String> robots = new LinkedHashMap<>();
        values.keySet().stream().filter(key -> key.startsWith(FixedPorts.ROBOT)).sorted().forEach(key -> robots.put(key, get(key)));
        try {
            return FixedPorts.setup(robots, get(FixedPorts.KEY), Integer.parseInt(get(FixedPorts.UDP_IDLE)),
                    Integer.parseInt(get("wss.port")), InetAddress.getByName(get("wss.bindAddress")));
        } catch (IllegalArgumentException e) {
            throw new ConfigFileException(source + ": " + e.getMessage());
        } catch (UnknownHostException e) {
            throw new IllegalStateException("wss.bindAddress was checked", e);
        }
    }

    /**
     * The pairs of wss.force.down and wss.force.up, each checked by its rule before.
     *
     * @throws ConfigFileException when a pair is in both (a bad configuration of {@code source})
     */
    Map<RobotPair, Force> forcedPairs(String source) throws ConfigFileException {
        Map<RobotPair, Force> forced = new LinkedHashMap<>();
        listed(get("wss.force.down"), RobotPair::listOf).forEach(pair -> forced.put(pair, Force.DOWN));
        ForcedUp up;
        try {
            up = ForcedUp.parse(get("wss.force.up"));
        } catch (IllegalArgumentException e) {
            throw new ConfigFileException(source + ": wss.force.up = '" + get("wss.force.up") + "' is not " + e.getMessage());
        }
        for (RobotPair pair : up.pairs()) {
            if (forced.put(pair, Force.UP) == Force.DOWN) {
                throw new ConfigFileException(source + ": the pair " + pair.first() + ":" + pair.second()
                        + " is in both wss.force.down and wss.force.up; force it one way");
            }
        }
        return forced;
    }

    /** The items of a list setting's value, checked by its rule before: none when it is empty. */
    private static <T> List<T> listed(String value, Function<String, List<T>> parse) {
        return value.isEmpty() ? List.of() : parse.apply(value);
    }
}
