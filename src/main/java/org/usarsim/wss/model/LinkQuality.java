package org.usarsim.wss.model;

/**
 * What a model may say of a link one way besides its strength, when links are shaped
 * (docs/shaping.md): its rate in bit/s (more than 0) and its delay in milliseconds (0 to 10,000),
 * and how the datagrams of its fixed UDP ports are lost ({@link DatagramLoss}; null: by the
 * server's loss table). A model that says nothing leaves them to the server's shaping settings.
 */
public record LinkQuality(long bitsPerSecond, int delayMs, DatagramLoss datagramLoss) {

    /** A rate and a delay, the datagrams lost by the server's loss table. */
    public LinkQuality(long bitsPerSecond, int delayMs) {
        this(bitsPerSecond, delayMs, null);
    }

    public LinkQuality {
        if (bitsPerSecond <= 0) {
            throw new IllegalArgumentException("a rate is more than 0 bit/s, not " + bitsPerSecond);
        }
        if (delayMs < 0 || delayMs > 10_000) {
            throw new IllegalArgumentException("a delay is 0 to 10000 ms, not " + delayMs);
        }
    }
}
