package org.usarsim.wss.recording;

import java.util.Map;

/**
 * The lines at the top of a recording (docs/replay.md): the format's version, the WSS that wrote
 * it, when the run started (ISO 8601, UTC), the model and every setting of the run (the model's and
 * the server's {@code wss.shaping*}), in the order written.
 */
public record Header(int version, String wssVersion, String started, String model, Map<String, String> settings) {

    public Header {
        settings = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(settings));
    }
}
