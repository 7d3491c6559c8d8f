package org.usarsim.wss.monitor;

import java.util.Map;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The run the monitor shows: its hub, its model with the run's values of the model's settings, its
 * shaping, and the address its control port listens on.
 */
public record Watched(Hub hub, PropagationModel model, Map<String, String> modelSettings, ShapingConfig shaping, String bindAddress) {

    public Watched {
        modelSettings = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(modelSettings));
    }
}
