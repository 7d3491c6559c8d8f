package org.usarsim.wss.gui;

import java.util.Map;
import java.util.logging.Logger;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The link shaping the window's next Start uses, which is also what the "Link shaping" dialog
 * shows: the values stored in the {@link WindowPreferences}, with the {@code wss.shaping*} keys a
 * --config file sets over them until the dialog stores new values with OK (from then on, the
 * stored values: what was entered). As {@link NextRunValues} does for a model's settings. Event thread.
 */
final class NextRunShaping {

    private static final Logger LOG = Logger.getLogger(NextRunShaping.class.getName());

    private final WindowPreferences preferences;
    /** The shaping keys the --config file sets, checked; empty without a file. */
    private final Map<String, String> file;
    /** Whether the dialog stored values in this session: the file's no longer go over them. */
    private boolean entered;

    NextRunShaping(WindowPreferences preferences, Map<String, String> file) {
        this.preferences = preferences;
        this.file = file == null ? Map.of() : Map.copyOf(file);
    }

    /** Each of the keys ({@link ShapingValues#KEYS}) with the value the next Start uses. */
    Map<String, String> values() {
        Map<String, String> values = preferences.shaping();
        if (entered) {
            return values;
        }
        for (String key : ShapingValues.KEYS) {
            String value = file.get(key);
            if (value == null) {
                continue;
            }
            String problem = ShapingValues.problem(key, value);
            if (problem == null) {
                values.put(key, value.strip());
            } else {
                LOG.warning("the file's " + key + " = '" + value + "' is refused (" + problem + "); using " + values.get(key));
            }
        }
        return values;
    }

    /** What the next Start hands the hub. */
    ShapingConfig config() {
        return ShapingValues.config(values());
    }

    /** The dialog stored what the user entered: the next Starts use the stored values. */
    void entered() {
        entered = true;
    }
}
