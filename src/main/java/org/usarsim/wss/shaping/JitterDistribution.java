package org.usarsim.wss.shaping;

import java.util.Locale;
import java.util.SplittableRandom;

/**
 * The distributions of a delay's jitter ({@code wss.shaping.jitterDistribution}), as netem names
 * them (tc-netem(8)): each draws a standard variate Z, and a grant's or datagram's delay is
 * delay + jitter x Z, never below 0 (docs/shaping.md, "Jitter"). Z as netem's kernel and
 * iproute2's tables define it:
 *
 * <ul>
 *   <li>{@link #UNIFORM}: Z uniform on [-1, 1) (netem without a table: delay +- jitter);
 *   <li>{@link #NORMAL}: Z standard normal, within netem's table range [-4, 4];
 *   <li>{@link #PARETO}: Z = 4/3 x (X - 1.5), X Pareto of shape 3 and scale 1 (mean 1.5), at most 4:
 *       iproute2's pareto table; Z is at least -2/3;
 *   <li>{@link #PARETONORMAL}: Z = (N(u) + 3 P(u)) / 4 at one uniform u, N and P the normal's and
 *       that Pareto's quantiles at u, within [-4, 4]: iproute2's paretonormal table.
 * </ul>
 *
 * Z is drawn by inverting the distribution at a uniform draw of the generator given, so a seed
 * gives the same draws on every machine.
 */
public enum JitterDistribution {
    UNIFORM(1),
    NORMAL(4),
    PARETO(4),
    PARETONORMAL(4);

    /** netem's tables hold Z x 8192 in 16 bits: |Z| at most 4. */
    private static final double TABLE_Z = 4;

    private final double most;

    JitterDistribution(double most) {
        this.most = most;
    }

    /** The largest Z it draws: what a direction's capacity makes room for (jitter x it). */
    public double most() {
        return most;
    }

    /** The name as the setting and netem write it. */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The distribution named {@code word} (case ignored, whitespace around it too), or null. */
    public static JitterDistribution of(String word) {
        String name = word == null ? "" : word.strip();
        for (JitterDistribution distribution : values()) {
            if (distribution.word().equalsIgnoreCase(name)) {
                return distribution;
            }
        }
        return null;
    }

    /** Draws Z from {@code random}. */
    public double draw(SplittableRandom random) {
        double u = random.nextDouble();
        return switch (this) {
            case UNIFORM -> 2 * u - 1;
            case NORMAL -> clamp(NormalQuantile.at(u));
            case PARETO -> pareto(u);
            case PARETONORMAL -> clamp((NormalQuantile.at(u) + 3 * pareto(u)) / 4);
        };
    }

    /** The Pareto variate of netem's table at {@code u} in [0, 1): 4/3 x ((1 - u)^(-1/3) - 1.5), at most 4. */
    static double pareto(double u) {
        return Math.min(TABLE_Z, (Math.pow(1 - u, -1.0 / 3) - 1.5) * 4 / 3);
    }

    private static double clamp(double z) {
        return Math.max(-TABLE_Z, Math.min(TABLE_Z, z));
    }
}
