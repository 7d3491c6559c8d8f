package org.usarsim.wss.model;

import java.util.Map;
import java.util.TreeMap;

/**
 * The values of a model's declared settings, as {@code PropagationModel.configure} is handed them:
 * strings by key ({@code usarsim.host}, {@code distance.cutoff}, ...), one for each {@link Setting}
 * the model declares. The server checked every value with its setting's rule before; a model reads
 * them with a fallback for any missing. Besides its own, every model is handed the run's seed,
 * {@link #SEED}, as a value (it may read it, never declare it: a {@code wss.*} key is the server's).
 */
public final class ModelSettings {

    /** The run's one seed, {@code wss.seed} (a Java long), passed to every model's configure as a value. */
    public static final String SEED = "wss.seed";

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

    public long getLong(String key, long fallback) {
        String value = values.get(key);
        return value == null ? fallback : Long.parseLong(value.strip());
    }

    /** A copy with {@code key} set to {@code value}, over any value it had. */
    public ModelSettings with(String key, String value) {
        Map<String, String> copy = new java.util.HashMap<>(values);
        copy.put(key, value);
        return new ModelSettings(copy);
    }

    public boolean getBoolean(String key, boolean fallback) {
        String value = values.get(key);
        return value == null ? fallback : Boolean.parseBoolean(value.strip());
    }

    public Map<String, String> asMap() {
        return new TreeMap<>(values);
    }
}
