package org.usarsim.wss.gui;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.logging.Logger;
import java.util.prefs.BackingStoreException;
import java.util.prefs.Preferences;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.ModelSettings;

/**
 * A model's settings as the GUI keeps them between runs: one {@link Preferences} node per model,
 * {@code org/usarsim/wss/models/<model name>} under the user's root, holding the keys the model
 * declares ({@link PropagationModel#settings()}) as strings. Every value is checked with its
 * {@link Setting}'s rule, when read and when stored. Headless mode never reads these.
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
     * Every key the model declares with its stored value (under its old name, {@code Setting.alias()},
     * when only that is stored), or its default when none is stored. A
     * stored value that breaks the key's rule (a hand-edited one) is replaced by the default, with
     * a WARNING; a stored key the model does not declare is left alone.
     */
    public Map<String, String> load(PropagationModel model) {
        Preferences node = node(model.name());
        Map<String, String> values = new LinkedHashMap<>();
        for (Setting setting : model.settings()) {
            String value = setting.defaultValue();
            String stored = node.get(setting.key(), null);
            if (stored == null && setting.alias() != null) {
                stored = node.get(setting.alias(), null); // stored before the key was renamed
            }
            if (stored != null) {
                String problem = setting.problem(stored);
                if (problem == null) {
                    value = stored.strip();
                } else {
                    LOG.warning("preferences " + node.absolutePath() + ": " + setting.key() + " = '" + stored + "' is not "
                            + problem + "; using the default " + value);
                }
            }
            values.put(setting.key(), value);
        }
        return values;
    }

    /** What {@link #load} gives, for {@code PropagationModel.configure}. */
    public ModelSettings settingValues(PropagationModel model) {
        return new ModelSettings(load(model));
    }

    /**
     * Stores these values (stripped) in the model's node and writes it out, a value given under a
     * key's old name under its key; keys not given keep what they had.
     *
     * @throws IllegalArgumentException when a key is not one the model declares or a value breaks
     *                                  its rule; nothing is stored then
     * @throws BackingStoreException    when the preferences cannot be written
     */
    public void store(PropagationModel model, Map<String, String> values) throws BackingStoreException {
        List<Setting> declared = model.settings();
        Map<String, String> renamed = new LinkedHashMap<>();
        values.forEach((key, value) -> {
            Setting old = Setting.find(declared, key) == null ? Setting.findAlias(declared, key) : null;
            renamed.put(old == null ? key : old.key(), value);
        });
        for (Map.Entry<String, String> entry : renamed.entrySet()) {
            Setting setting = Setting.find(declared, entry.getKey());
            if (setting == null) {
                throw new IllegalArgumentException(entry.getKey() + " is not a setting of " + model.name());
            }
            String problem = setting.problem(entry.getValue());
            if (problem != null) {
                throw new IllegalArgumentException(entry.getKey() + " = '" + entry.getValue() + "' is not " + problem);
            }
        }
        Preferences node = node(model.name());
        renamed.forEach((key, value) -> node.put(key, value.strip()));
        node.flush();
    }
}
