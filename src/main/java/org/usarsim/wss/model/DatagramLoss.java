package org.usarsim.wss.model;

import java.util.random.RandomGenerator;

/**
 * How a model loses the datagrams of a fixed UDP port one way, instead of the server's loss table
 * ({@code wss.shaping.loss}), when links are shaped: given with a {@link LinkQuality}. Asked once
 * per datagram as it goes on the air, on the port's thread, with the port's own seeded generator
 * (draw from it, not from a generator of the model's own, so that a port's losses depend on its
 * seed alone) and the server's time in nanoseconds. Must be thread-safe: every port of the pair
 * asks it.
 */
@FunctionalInterface
public interface DatagramLoss {

    /** Whether a datagram of {@code bytes} bytes sent at {@code nowNs} is lost. */
    boolean lost(int bytes, long nowNs, RandomGenerator random);
}
