package org.usarsim.wss.gui;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.logging.Logger;
import java.util.prefs.BackingStoreException;
import java.util.prefs.Preferences;
import org.usarsim.wss.app.Settings;
import org.usarsim.wss.model.ModelSettings;

/**
 * A model's settings as the GUI keeps them between runs: one {@link Preferences} node per model,
 * {@code org/usarsim/wss/models/<model name>} under the user's root, holding the model keys
 * (usarsim.*, distance.*, obstacle.*) as strings. Every value is checked with {@link Settings}'
 * rule, when read and when stored. Headless mode never reads these.
 */
public final class ModelPreferences {

    private static final Logger LOG = Logger.getLogger(ModelPreferences.class.getName());

    private final Preferences root;

    /** The user's preferences: {@code Preferences.userRoot().node("org/usarsim/wss/models")}. */
    public ModelPreferences() {
        this(Preferences.userRoot().node("org/usarsim/wss/models"));
    }

    /** The model nodes live under {@code root} (tests pass a throw-away node). */
    public ModelPreferences(Preferences root) {
        this.root = root;
    }

    /** The node of one model. */
    Preferences node(String modelName) {
        return root.node(modelName);
    }

    /**
     * Every model key with its stored value, or its default when none is stored. A stored value
     * that breaks the key's rule (a hand-edited one) is replaced by the default, with a WARNING.
     */
    public Map<String, String> load(String modelName) {
        Preferences node = node(modelName);
        Map<String, String> values = new LinkedHashMap<>(Settings.modelDefaults());
        for (Map.Entry<String, String> entry : values.entrySet()) {
            String stored = node.get(entry.getKey(), null);
            if (stored == null) {
                continue;
            }
            String problem = Settings.problem(entry.getKey(), stored);
            if (problem == null) {
                entry.setValue(stored.strip());
            } else {
                LOG.warning("preferences " + node.absolutePath() + ": " + entry.getKey() + " = '" + stored + "' is not "
                        + problem + "; using the default " + entry.getValue());
            }
        }
        return values;
    }

    /** What {@link #load} gives, for {@code PropagationModel.configure}. */
    public ModelSettings settings(String modelName) {
        return new ModelSettings(load(modelName));
    }

    /**
     * Stores these values (stripped) in the model's node and writes it out; keys not given keep
     * what they had.
     *
     * @throws IllegalArgumentException when a key is not a model key or a value breaks its rule;
     *                                  nothing is stored then
     * @throws BackingStoreException    when the preferences cannot be written
     */
    public void store(String modelName, Map<String, String> values) throws BackingStoreException {
        Map<String, String> defaults = Settings.modelDefaults();
        for (Map.Entry<String, String> entry : values.entrySet()) {
            if (!defaults.containsKey(entry.getKey())) {
                throw new IllegalArgumentException(entry.getKey() + " is not a model setting");
            }
            String problem = Settings.problem(entry.getKey(), entry.getValue());
            if (problem != null) {
                throw new IllegalArgumentException(entry.getKey() + " = '" + entry.getValue() + "' is not " + problem);
            }
        }
        Preferences node = node(modelName);
        values.forEach((key, value) -> node.put(key, value.strip()));
        node.flush();
    }
}
