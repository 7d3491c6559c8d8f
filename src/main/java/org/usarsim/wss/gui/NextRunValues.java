package org.usarsim.wss.gui;

import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.logging.Logger;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.ModelSettings;

/**
 * The setting values a model's next start uses, which are also those its dialog shows: the model's
 * stored preferences, with the keys a --config file sets over them until the model's dialog stores
 * new values with OK (from then on, the stored values: what was entered). Event thread.
 */
final class NextRunValues {

    private static final Logger LOG = Logger.getLogger(NextRunValues.class.getName());

    private final ModelPreferences preferences;
    /** The model keys the --config file sets, checked; empty without a file. */
    private final Map<String, String> file;
    /** The models whose dialog stored values in this session: the file's no longer go over them. */
    private final Set<String> entered = new HashSet<>();

    NextRunValues(ModelPreferences preferences, ModelSettings file) {
        this.preferences = preferences;
        this.file = file == null ? Map.of() : file.asMap();
    }

    /** Every key the model declares with the value its next start uses. */
    Map<String, String> values(PropagationModel model) {
        Map<String, String> values = preferences.load(model);
        if (entered.contains(model.name())) {
            return values;
        }
        for (Setting setting : model.settings()) {
            String value = file.get(setting.key());
            if (value == null) {
                continue;
            }
            String problem = setting.problem(value);
            if (problem == null) {
                values.put(setting.key(), value);
            } else {
                LOG.warning(model.name() + ": the file's " + setting.key() + " = '" + value + "' is not " + problem
                        + "; using " + values.get(setting.key()));
            }
        }
        return values;
    }

    /** The model's dialog stored what the user entered: its next starts use the stored values. */
    void entered(PropagationModel model) {
        entered.add(model.name());
    }
}
