package org.usarsim.wss.model.simulator;

import java.util.List;
import java.util.SplittableRandom;
import java.util.random.RandomGenerator;
import java.util.concurrent.ConcurrentHashMap;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.RobotPair;

/**
 * Log-normal shadowing correlated in space (docs/models.md, "Shadowing"): a term of {@code sigma}
 * dB added to a pair's strength, the same wherever the two robots stand still, changing little
 * while they move less than the decorrelation distance. A pure function of the seed, the pair's
 * names and the two positions: a second run, or the same positions asked again, gives the same
 * values; nothing depends on the poll interval or on the way the robots went.
 *
 * <p>Each pair has a field over the six coordinates of its two robots (the first of the pair's
 * names first), a sum of {@link #FEATURES} cosines with random directions and phases drawn from a
 * generator seeded from the seed and the pair's names. With the directions drawn from the
 * multivariate Cauchy law of scale 1/distance, the field's autocorrelation is exactly
 * Gudmundson's exponential one, exp(-moved / distance) when one robot moves (and
 * exp(-sqrt(movedA^2 + movedB^2) / distance) when both do); its values are normal within
 * 1.5/{@link #FEATURES} of kurtosis. Thread-safe: a pair's field is made once, at its first use.
 */
public final class Shadowing {

    /**
     * The settings: the sigma in dB (0: none), the decorrelation distance in metres. The seed is the
     * run's, {@link ModelSettings#SEED} ({@code wss.seed}), which the server passes as a value.
     */
    public static final String SIGMA = "shadowing.sigma";
    public static final String DISTANCE = "shadowing.distance";
    /** The two, in the order the CSV event log writes them at a run's start (before wss.seed). */
    public static final List<String> KEYS = List.of(SIGMA, DISTANCE);

    /** The cosines summed per pair. */
    static final int FEATURES = 64;

    /** No shadowing: 0 dB everywhere. */
    public static final Shadowing NONE = new Shadowing(0, 1, 0);

    private final double sigma;
    private final double distance;
    private final long seed;
    private final double scale;
    private final ConcurrentHashMap<RobotPair, double[]> fields = new ConcurrentHashMap<>();

    /** A field of {@code sigma} dB, decorrelated over {@code distance} metres (more than 0), drawn from {@code seed}. */
    public Shadowing(double sigma, double distance, long seed) {
        if (!(distance > 0) || !(sigma >= 0)) {
            throw new IllegalArgumentException("a sigma of 0 dB or more and a distance above 0 m, not " + sigma + " and " + distance);
        }
        this.sigma = sigma;
        this.distance = distance;
        this.seed = seed;
        this.scale = sigma * Math.sqrt(2.0 / FEATURES);
    }

    /** The shadowing a run's checked settings ask for: {@link #NONE} with a sigma of 0. */
    static Shadowing of(ModelSettings settings) {
        double sigma = settings.getDouble(SIGMA, 0);
        return sigma > 0 ? new Shadowing(sigma, settings.getDouble(DISTANCE, 5), settings.getLong(ModelSettings.SEED, 0)) : NONE;
    }

    /** The term in dB between two robots where they are: 0 without shadowing; the same whichever is given first. */
    public double db(ReportedRobot a, ReportedRobot b) {
        if (sigma == 0) {
            return 0;
        }
        RobotPair pair = RobotPair.of(a.name(), b.name());
        ReportedRobot first = pair.first().equals(a.name()) ? a : b;
        ReportedRobot second = first == a ? b : a;
        double[] at = {first.x(), first.y(), first.z(), second.x(), second.y(), second.z()};
        double[] field = fields.computeIfAbsent(pair, this::field);
        double sum = 0;
        for (int f = 0; f < FEATURES; f++) {
            int base = f * 7;
            double phase = field[base + 6];
            for (int i = 0; i < 6; i++) {
                phase += field[base + i] * at[i];
            }
            sum += Math.cos(phase);
        }
        return scale * sum;
    }

    /** The pair's directions (Cauchy: a normal vector over the absolute value of a normal, over the distance) and phases. */
    private double[] field(RobotPair pair) {
        SplittableRandom random = new SplittableRandom(pairSeed(seed, pair));
        double[] field = new double[FEATURES * 7];
        for (int f = 0; f < FEATURES; f++) {
            double divisor = Math.abs(gaussian(random)) * distance;
            while (divisor == 0) {
                divisor = Math.abs(gaussian(random)) * distance;
            }
            for (int i = 0; i < 6; i++) {
                field[f * 7 + i] = gaussian(random) / divisor;
            }
            field[f * 7 + 6] = random.nextDouble() * 2 * Math.PI;
        }
        return field;
    }

    /** A standard normal draw by the polar method, written here so that the draws do not change with the JDK's own algorithm. */
    public static double gaussian(RandomGenerator random) {
        double u;
        double v;
        double s;
        do {
            u = random.nextDouble() * 2 - 1;
            v = random.nextDouble() * 2 - 1;
            s = u * u + v * v;
        } while (s >= 1 || s == 0);
        return u * Math.sqrt(-2 * Math.log(s) / s);
    }

    /** The seed of a pair's generator: the run's seed and the two names, mixed (FNV-1a), stable across runs and machines. */
    static long pairSeed(long seed, RobotPair pair) {
        long hash = 0xcbf29ce484222325L ^ seed;
        String names = pair.first() + '\0' + pair.second();
        for (int i = 0; i < names.length(); i++) {
            hash = (hash ^ names.charAt(i)) * 0x100000001b3L;
        }
        return hash;
    }

    /** The sigma in dB: 0 without shadowing. */
    public double sigma() {
        return sigma;
    }
}
