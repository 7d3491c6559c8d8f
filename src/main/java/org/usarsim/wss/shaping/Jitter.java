package org.usarsim.wss.shaping;

import java.util.SplittableRandom;

/**
 * A delay's jitter ({@code wss.shaping.jitter}, a pin's {@code Jitter}), the stage after the
 * {@link Delay} (docs/shaping.md, "Jitter"): bytes the delay lets go at t may be written at
 * t + jitter x Z, Z drawn from its {@link JitterDistribution} with a seeded generator, once per
 * grant (a TCP direction) or per datagram (a fixed UDP port); the delay and the jitter together
 * are never below 0, so nothing is due before it is off the air (netem sends a packet whose
 * drawn delay is negative at once). With a jitter of 0 it draws nothing and adds nothing.
 * Whether what it lets go sooner may overtake what is before it is its caller's: never on a TCP
 * link ({@link OnTheAir} writes in order), on a fixed UDP port as {@code wss.shaping.reorder} says.
 */
final class Jitter implements AfterAir {

    private final Delay delay;
    private final JitterDistribution distribution;
    private final SplittableRandom random;
    private int ms;

    /** The jitter after {@code delay}, of {@code ms}, its draws from a generator seeded with {@code seed}. */
    Jitter(Delay delay, JitterDistribution distribution, long seed, int ms) {
        this.delay = delay;
        this.distribution = distribution;
        this.random = new SplittableRandom(seed);
        this.ms = ms;
    }

    /** The jitter from now on, in milliseconds. */
    void set(int ms) {
        this.ms = ms;
    }

    int ms() {
        return ms;
    }

    @Override
    public long dueAt(long delayedNs) {
        if (ms == 0) {
            return delayedNs;
        }
        long extra = Math.round(ms * 1e6 * distribution.draw(random));
        return delayedNs + Math.max(-delay.holdsNs(), extra);
    }

    /** The most it adds: the jitter times the distribution's largest Z. */
    @Override
    public long holdsNs() {
        return (long) Math.ceil(ms * 1e6 * distribution.most());
    }
}
