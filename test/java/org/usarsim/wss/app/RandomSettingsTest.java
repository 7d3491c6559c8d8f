package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Map;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/** The event log's SETTING lines: the shadowing's settings and the seed, with the run's values, for a model that declares them. */
class RandomSettingsTest {

    @Test
    void theShadowingsSettingsAndTheSeedOfTheRunInTheirOrder() {
        assertEquals(Map.of("shadowing.sigma", "10", "shadowing.distance", "5", "radio.seed", "42"),
                Server.randomSettings(new DistanceOnlyPropagationModel(), new ModelSettings(Map.of("shadowing.sigma", "10", "radio.seed", "42"))));
        assertEquals(java.util.List.of("shadowing.sigma", "shadowing.distance", "radio.seed"), java.util.List.copyOf(
                Server.randomSettings(new DistanceOnlyPropagationModel(), new ModelSettings(Map.of())).keySet()));
        assertEquals(Map.of(), Server.randomSettings(new NoopPropagationModel(), new ModelSettings(Map.of())));
    }
}
