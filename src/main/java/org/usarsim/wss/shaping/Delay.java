package org.usarsim.wss.shaping;

/**
 * A direction's delay ({@code wss.shaping.delayMs}, a pin's {@code Delay}, a model's own), the
 * stage after the air of every shaped TCP direction and fixed UDP port: bytes whose last bit is
 * on the air at t may be written at t + the delay. A new delay applies to bytes whose last bit is
 * not yet on the air; the others keep theirs.
 */
final class Delay implements AfterAir {

    private int ms;

    Delay(int ms) {
        this.ms = ms;
    }

    /** The delay from now on, in milliseconds. */
    void set(int ms) {
        this.ms = ms;
    }

    int ms() {
        return ms;
    }

    @Override
    public long dueAt(long offAirNs) {
        return offAirNs + holdsNs();
    }

    @Override
    public long holdsNs() {
        return ms * 1_000_000L;
    }
}
