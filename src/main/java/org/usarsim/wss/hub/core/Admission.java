package org.usarsim.wss.hub.core;

import java.net.InetSocketAddress;

/**
 * Whether a connection accepted on a WSS port may be forwarded ({@link HubCore#admit}): null
 * refusal, where to, the pair's counters, and its live conditions each way (from the port's source
 * to its target: {@code up}).
 */
public record Admission(String refusal, InetSocketAddress target, PairStats stats,
        LiveCondition up, LiveCondition down) {
}
