package org.usarsim.wss.shaping;

import java.util.SplittableRandom;

/**
 * A run's jitter settings (docs/shaping.md, "Jitter"): the jitter every shaped direction gets
 * unless an operator pins another ({@code wss.shaping.jitter}, ms; 0: none), its distribution
 * ({@code wss.shaping.jitterDistribution}), whether a fixed UDP port's datagrams may overtake each
 * other ({@code wss.shaping.reorder}; a TCP link's bytes never do), and the run's seed
 * ({@code wss.seed}), from which each direction's generator is seeded.
 */
public record JitterConfig(int ms, JitterDistribution distribution, boolean reorder, long seed) {

    /** The default seed: a run is repeatable unless told otherwise. */
    public static final long DEFAULT_SEED = 0;
    /** No jitter: netem's default distribution, in order, the default seed. */
    public static final JitterConfig NONE = new JitterConfig(0, JitterDistribution.UNIFORM, false, DEFAULT_SEED);

    public JitterConfig {
        if (ms < ShapingConfig.MIN_DELAY_MS || ms > ShapingConfig.MAX_JITTER_MS) {
            throw new IllegalArgumentException(ShapingConfig.JITTER + ": " + ms + " is not 0 to " + ShapingConfig.MAX_JITTER_MS);
        }
        if (distribution == null) {
            throw new IllegalArgumentException(ShapingConfig.JITTER_DISTRIBUTION + ": none");
        }
    }

    /**
     * The seed of one direction's jitter, from the run's seed, the robots it goes between and
     * {@code stream} (a fixed UDP port's number and direction, say): the same run draws the same
     * jitters, and two directions draw apart.
     */
    public long seedFor(String from, String to, long stream) {
        SplittableRandom mixer = new SplittableRandom(seed ^ (31L * from.hashCode() + to.hashCode()) * 0x9E3779B97F4A7C15L);
        return mixer.nextLong() + stream * 0xBF58476D1CE4E5B9L;
    }
}
