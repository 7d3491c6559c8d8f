package org.usarsim.wss.gui;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The link shaping settings as the window keeps, shows and starts them: text by key
 * ({@code wss.shaping}, {@code wss.shaping.rates}, {@code wss.shaping.delayMs},
 * {@code wss.shaping.airtime}, {@code wss.shaping.queueMs}, the jitter's three keys, docs/shaping.md), each checked by the
 * rule a properties file's are checked with, {@link ShapingConfig#from} (the rates by
 * {@link RateTable#parse}, the delay by {@link ShapingConfig#parseDelayMs}). No state.
 */
final class ShapingValues {

    /** The keys, in the dialog's order. */
    static final List<String> KEYS = List.of(ShapingConfig.SHAPING, ShapingConfig.RATES, ShapingConfig.DELAY_MS, ShapingConfig.AIRTIME,
            ShapingConfig.QUEUE_MS, ShapingConfig.JITTER, ShapingConfig.JITTER_DISTRIBUTION, ShapingConfig.REORDER);

    private ShapingValues() {
    }

    /** Each key's default: links not shaped, the default rate table, 2 ms, shared airtime, a queue of 20 ms. */
    static Map<String, String> defaults() {
        ShapingConfig off = ShapingConfig.OFF;
        Map<String, String> values = new LinkedHashMap<>();
        values.put(ShapingConfig.SHAPING, off.on() ? "on" : "off");
        values.put(ShapingConfig.RATES, off.rates().toString());
        values.put(ShapingConfig.DELAY_MS, String.valueOf(off.delayMs()));
        values.put(ShapingConfig.AIRTIME, String.valueOf(off.airtime()));
        values.put(ShapingConfig.QUEUE_MS, String.valueOf(off.queueMs()));
        values.put(ShapingConfig.JITTER, String.valueOf(off.jitter().ms()));
        values.put(ShapingConfig.JITTER_DISTRIBUTION, off.jitter().distribution().word());
        values.put(ShapingConfig.REORDER, String.valueOf(off.jitter().reorder()));
        return values;
    }

    /**
     * Why {@code value} is refused for {@code key}, in the rule's words without the key
     * ({@code soon is not a whole number of milliseconds}), or null when it is accepted.
     */
    static String problem(String key, String value) {
        try {
            ShapingConfig.from(Map.of(key, value == null ? "" : value));
            return null;
        } catch (IllegalArgumentException e) {
            String prefix = key + ": ";
            String message = String.valueOf(e.getMessage());
            return message.startsWith(prefix) ? message.substring(prefix.length()) : message;
        }
    }

    /** The run's settings these values give. @throws IllegalArgumentException for a refused value, naming its key */
    static ShapingConfig config(Map<String, String> values) {
        return ShapingConfig.from(values);
    }
}
