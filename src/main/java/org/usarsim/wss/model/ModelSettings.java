package org.usarsim.wss.model;

import java.util.Map;
import java.util.TreeMap;

/**
 * The settings handed to a model: string values by property name ({@code usarsim.host},
 * {@code distance.cutoff}, ...). Values given here were already checked by the server; a model
 * reads them with a default for any that is missing.
 */
public final class ModelSettings {

    private final Map<String, String> values;

    public ModelSettings(Map<String, String> values) {
        this.values = Map.copyOf(values);
    }

    public String getString(String key, String fallback) {
        return values.getOrDefault(key, fallback);
    }

    public double getDouble(String key, double fallback) {
        String value = values.get(key);
        return value == null ? fallback : Double.parseDouble(value.strip());
    }

    public int getInt(String key, int fallback) {
        String value = values.get(key);
        return value == null ? fallback : Integer.parseInt(value.strip());
    }

    public Map<String, String> asMap() {
        return new TreeMap<>(values);
    }
}
