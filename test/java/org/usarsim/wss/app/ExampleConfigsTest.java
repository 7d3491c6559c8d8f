package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The properties files in docs/examples are valid headless configurations. */
class ExampleConfigsTest {

    @ParameterizedTest
    @CsvSource({
        "docs/examples/corridor.properties, DistanceOnlyPropagationModel",
        "docs/examples/building.properties, ObstaclePropagationModel",
    })
    void examplesLoad(String file, String model) throws Exception {
        ConfigFile settings = ConfigFile.load(Path.of(file));
        assertEquals(model, settings.modelName());
        assertEquals("127.0.0.1", settings.get("usarsim.host"));
        assertEquals("7435", settings.get("usarsim.port"));
        assertEquals("50000", settings.get("wss.port"));
    }

    @Test
    void theRosbridgeExampleLoads() throws Exception {
        ConfigFile settings = ConfigFile.load(Path.of("docs/examples/building-rosbridge.properties"));
        assertEquals("ObstaclePropagationModel", settings.modelName());
        assertEquals("rosbridge", settings.modelValues().getString("positions", null));
        assertEquals("ws://127.0.0.1:9090", settings.modelValues().getString("rosbridge.url", null));
        assertEquals("/map", settings.modelValues().getString("rosbridge.map", null));
    }
}
