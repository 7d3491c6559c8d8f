package org.usarsim.wss.hub.tcp;

import org.usarsim.wss.hub.core.LiveCondition;
import org.usarsim.wss.shaping.Airtime;
import org.usarsim.wss.shaping.JitterConfig;

/**
 * What a shaped link forwards by (docs/shaping.md): its pair's live condition each way (the
 * core's one value per ordered pair, {@code up} from the port's source to its target), the
 * robots' radios, and each direction's queue ({@code wss.shaping.queueMs}), and the jitter's
 * distribution and seed. The time is the link's clock, the hub's.
 */
public record Shaping(Airtime airtime, LiveCondition up, LiveCondition down, int queueMs, JitterConfig jitter) {
}
