package org.usarsim.wss.model;

import java.util.Collection;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/** What is done with a list of settings (a model's declaration): each of {@link Setting}'s static methods of the same name says what. */
final class SettingLists {

    private SettingLists() {
    }

    static Map<String, String> checked(Collection<Setting> declared, Map<String, String> given) {
        Map<String, String> values = new LinkedHashMap<>(given);
        for (Setting setting : declared) {
            if (setting.alias() != null && values.containsKey(setting.alias())) {
                String old = values.remove(setting.alias());
                values.putIfAbsent(setting.key(), old);
            }
            String value = values.computeIfAbsent(setting.key(), key -> setting.defaultValue());
            String problem = setting.problem(value);
            if (problem != null) {
                throw new IllegalArgumentException(setting.key() + ": '" + value + "' is not " + problem);
            }
        }
        return values;
    }

    static Map<String, String> defaults(List<Setting> settings) {
        Map<String, String> values = new LinkedHashMap<>();
        settings.forEach(setting -> values.put(setting.key(), setting.defaultValue()));
        return values;
    }

    static Setting find(List<Setting> settings, String key) {
        return settings.stream().filter(setting -> setting.key().equals(key)).findFirst().orElse(null);
    }

    static Setting findAlias(Collection<Setting> settings, String oldKey) {
        return settings.stream().filter(setting -> oldKey.equals(setting.alias())).findFirst().orElse(null);
    }

    static String declarationProblem(List<Setting> settings) {
        if (settings == null) {
            return "settings() returned null";
        }
        Set<String> keys = new HashSet<>();
        for (Setting setting : settings) {
            if (setting == null) {
                return "settings() holds null";
            }
            if (setting.key().isBlank() || setting.key().chars().anyMatch(Character::isWhitespace)) {
                return "setting key '" + setting.key() + "' is blank or holds whitespace";
            }
            if (setting.key().startsWith("wss.")) {
                return "setting " + setting.key() + ": the wss.* keys are the server's";
            }
            if (!keys.add(setting.key())) {
                return "setting " + setting.key() + " is declared twice";
            }
            String problem = setting.problem(setting.defaultValue());
            if (problem != null) {
                return "setting " + setting.key() + ": the default '" + setting.defaultValue() + "' is not " + problem;
            }
        }
        return null;
    }
}
