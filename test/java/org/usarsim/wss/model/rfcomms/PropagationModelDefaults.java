package org.usarsim.wss.model.rfcomms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.util.List;
import java.util.Map;
import org.usarsim.wss.model.Setting;

/** Checks declared defaults. */
final class PropagationModelDefaults {

    private PropagationModelDefaults() {
    }

    static void check(List<Setting> declared, Map<String, String> defaults) {
        defaults.forEach((key, value) -> {
            Setting setting = Setting.find(declared, key);
            assertNotNull(setting, key);
            assertEquals(value, setting.defaultValue(), key);
        });
    }
}
