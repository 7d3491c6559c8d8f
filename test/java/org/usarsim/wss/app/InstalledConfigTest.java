package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;

/**
 * The Debian package's /etc/wss/wss.properties (src/deb/wss.properties): every property the server
 * and the built-in models declare is there, commented out, with its default; nothing is set, so
 * the service runs on the defaults until an operator uncomments a line.
 */
class InstalledConfigTest {

    private static final Path FILE = Path.of("src/deb/wss.properties");

    @Test
    void everyDeclaredPropertyIsCommentedWithItsDefaultAndNothingIsSet() throws Exception {
        Properties set = ConfigFile.read(FILE);
        assertEquals(Set.of(), set.stringPropertyNames(), "the file sets nothing");
        Set<String> lines = Files.readAllLines(FILE).stream().map(String::strip).collect(Collectors.toSet());
        List<Setting> declared = new ArrayList<>(ConfigKeys.SERVER);
        for (PropagationModel model : ConfigFile.defaults().catalog().models()) {
            declared.addAll(model.settings());
        }
        List<String> missing = declared.stream()
                .map(setting -> ("#" + setting.key() + " = " + setting.defaultValue()).strip())
                .filter(line -> !lines.contains(line)).distinct().toList();
        assertEquals(List.of(), missing, "lines missing from " + FILE);
    }

    @Test
    void theServiceStartsOnIt() throws Exception {
        ConfigFile settings = ConfigFile.load(FILE);
        assertEquals(ConfigFile.defaults().hubConfig(), settings.hubConfig());
        assertTrue(settings.ignoredKeys().isEmpty());
    }
}
