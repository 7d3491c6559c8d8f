package org.usarsim.wss.model;

import java.util.Map;
import java.util.TreeMap;

/**
 * The values of a model's declared settings, as {@code PropagationModel.configure} is handed them:
 * strings by key ({@code usarsim.host}, {@code distance.cutoff}, ...), one for each {@link Setting}
 * the model declares. The server checked every value with its setting's rule before; a model reads
 * them with a fallback for any missing.
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

    public boolean getBoolean(String key, boolean fallback) {
        String value = values.get(key);
        return value == null ? fallback : Boolean.parseBoolean(value.strip());
    }

    public Map<String, String> asMap() {
        return new TreeMap<>(values);
    }
}
