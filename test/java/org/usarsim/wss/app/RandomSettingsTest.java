package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/** The event log's SETTING lines (the shadowing's settings the model declares, then the run's seed) and the seed every model is handed. */
class RandomSettingsTest {

    @Test
    void theShadowingsSettingsAndTheSeedOfTheRunInTheirOrder() {
        assertEquals(Map.of("shadowing.sigma", "10", "shadowing.distance", "5", "wss.seed", "42"),
                Server.randomSettings(new DistanceOnlyPropagationModel(), new ModelSettings(Map.of("shadowing.sigma", "10", "wss.seed", "42"))));
        assertEquals(List.of("shadowing.sigma", "shadowing.distance", "wss.seed"), List.copyOf(
                Server.randomSettings(new DistanceOnlyPropagationModel(), new ModelSettings(Map.of())).keySet()));
        assertEquals(Map.of("wss.seed", "0"), Server.randomSettings(new NoopPropagationModel(), new ModelSettings(Map.of())),
                "the run's seed whatever the model: the jitter draws from it too");
    }

    @Test
    void everyModelIsHandedTheRunsSeedAsAValue() throws Exception {
        Properties properties = new Properties();
        properties.setProperty("wss.port", "0");
        properties.setProperty("wss.seed", "-9000000000");
        HubConfig config = ConfigFile.of(properties, "t").hubConfig();
        ModelSettings values = Server.withRunSeed(new ModelSettings(Map.of("shadowing.sigma", "10", "wss.seed", "3")), config);
        assertEquals(-9_000_000_000L, values.getLong(ModelSettings.SEED, 0), "the hub's, over any other");
        assertEquals("10", values.getString("shadowing.sigma", null));
        assertEquals("0", Server.withRunSeed(new ModelSettings(Map.of()), ConfigFile.of(new Properties(), "t").hubConfig())
                .getString("wss.seed", null), "the jitter's default");
    }

    @Test
    void theRecordingsHeaderHasTheRunsSeedAndNoOtherSeed() throws Exception {
        Properties properties = new Properties();
        properties.setProperty("wss.seed", "12");
        HubConfig config = ConfigFile.of(properties, "t").hubConfig();
        Map<String, String> header = Server.recordedSettings(new DistanceOnlyPropagationModel(),
                Server.withRunSeed(new ModelSettings(Map.of()), config), config.shaping());
        assertEquals("12", header.get("wss.seed"));
        assertEquals(List.of("wss.seed"), header.keySet().stream().filter(key -> key.endsWith("seed")).toList());
    }
}
