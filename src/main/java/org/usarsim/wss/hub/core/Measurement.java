package org.usarsim.wss.hub.core;

import java.util.Optional;
import org.usarsim.wss.model.LinkQuality;

/** What the model said of a pair one way, asked by the hub without its lock: the strength (dBm, NaN unknown) and its own rate and delay if it gives them. */
public record Measurement(double strength, Optional<LinkQuality> quality) {

    /** Nothing known yet. */
    public static final Measurement NONE = new Measurement(Double.NaN, Optional.empty());
}
