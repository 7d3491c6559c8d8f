package org.usarsim.wss.shaping;

import java.util.Map;
import java.util.Objects;

/**
 * The shaping settings of one run, checked once and then fixed: whether links are shaped at all
 * ({@code wss.shaping}), the rate for each signal strength ({@code wss.shaping.rates}), the delay
 * every byte waits besides its time on the air ({@code wss.shaping.delayMs}), and whether the
 * robots' radios share their airtime between their links ({@code wss.shaping.airtime}).
 * docs/shaping.md describes each.
 *
 * @param on whether links are shaped; off, every other value is checked but unused
 * @param rates the rate of a pair for its strength
 * @param delayMs the delay, from {@link #MIN_DELAY_MS} to {@link #MAX_DELAY_MS}
 * @param airtime whether links sharing a robot share its radio's airtime
 * @param queueMs the most a direction holds beyond its delay, in milliseconds at its rate
 * @param loss the share of datagrams a pair loses for its strength ({@code wss.shaping.loss}; UDP only)
 * @param jitter the delay's jitter, its distribution, whether datagrams may be reordered, the seed
 */
public record ShapingConfig(boolean on, RateTable rates, int delayMs, boolean airtime, int queueMs, LossTable loss,
        JitterConfig jitter) {

    public static final String SHAPING = "wss.shaping";
    public static final String RATES = "wss.shaping.rates";
    public static final String DELAY_MS = "wss.shaping.delayMs";
    public static final String AIRTIME = "wss.shaping.airtime";
    public static final String LOSS = "wss.shaping.loss";
    /** The most a direction queues, in milliseconds of its rate (issue 27; docs/shaping.md, "The queue"). */
    public static final String QUEUE_MS = "wss.shaping.queueMs";
    /**
     * What an 802.11 radio keeps queued under a saturating stream: Linux's mac80211 runs CoDel
     * on each station's queues with a 20 ms target, and the WSS, which never drops a TCP byte,
     * holds its limit as long as a stream saturates it (docs/shaping.md, "The queue").
     */
    public static final int DEFAULT_QUEUE_MS = 20;
    /** Below 10 ms a direction could not keep its radio busy (it books its airtime 8 ms ahead). */
    public static final int MIN_QUEUE_MS = 10;
    public static final int MAX_QUEUE_MS = 10_000;

    public static final int DEFAULT_DELAY_MS = 2;
    public static final int MIN_DELAY_MS = 0;
    public static final int MAX_DELAY_MS = 10_000;

    /** The delay's jitter, in ms (docs/shaping.md, "Jitter"); 0: none. */
    public static final String JITTER = "wss.shaping.jitter";
    /** The jitter's distribution, as netem names them: uniform, normal, pareto, paretonormal. */
    public static final String JITTER_DISTRIBUTION = "wss.shaping.jitterDistribution";
    /** Whether a fixed UDP port's datagrams may overtake each other by their jitter (a TCP link's bytes never do). */
    public static final String REORDER = "wss.shaping.reorder";
    /** The run's seed, from which every random draw of the run is seeded (the jitter's here). */
    public static final String SEED = "wss.seed";
    public static final int MAX_JITTER_MS = 10_000;

    /** No shaping: links forward as fast as the robots and the machine allow. The default. */
    public static final ShapingConfig OFF = new ShapingConfig(false, RateTable.DEFAULT, DEFAULT_DELAY_MS, true);

    public ShapingConfig {
        Objects.requireNonNull(rates, "rates");
        Objects.requireNonNull(loss, "loss");
        Objects.requireNonNull(jitter, "jitter");
        String problem = delayProblem(delayMs);
        if (problem != null) {
            throw new IllegalArgumentException(DELAY_MS + ": " + delayMs + " " + problem);
        }
        String queueProblem = queueProblem(queueMs);
        if (queueProblem != null) {
            throw new IllegalArgumentException(QUEUE_MS + ": " + queueMs + " " + queueProblem);
        }
    }

    /** With the default queue ({@link #DEFAULT_QUEUE_MS}) and the default loss table. */
    public ShapingConfig(boolean on, RateTable rates, int delayMs, boolean airtime) {
        this(on, rates, delayMs, airtime, DEFAULT_QUEUE_MS, LossTable.DEFAULT);
    }

    /** Without jitter ({@link JitterConfig#NONE}). */
    public ShapingConfig(boolean on, RateTable rates, int delayMs, boolean airtime, int queueMs, LossTable loss) {
        this(on, rates, delayMs, airtime, queueMs, loss, JitterConfig.NONE);
    }

    /**
     * The settings {@code values} give by key ({@link #SHAPING}, {@link #RATES}, {@link #DELAY_MS},
     * {@link #AIRTIME}, {@link #LOSS}; a key not there takes its default; other keys are ignored), each checked,
     * even with shaping off, so that a mistake is found before the day it is switched on.
     *
     * @throws IllegalArgumentException for the first bad value, naming its key and the value:
     *     {@code wss.shaping.delayMs: -1 is below 0}
     */
    public static ShapingConfig from(Map<String, String> values) {
        String shaping = value(values, SHAPING, "off");
        boolean on;
        if (shaping.equalsIgnoreCase("on")) {
            on = true;
        } else if (shaping.equalsIgnoreCase("off")) {
            on = false;
        } else {
            throw refused(SHAPING, shaping, "is not on or off");
        }
        String ratesText = value(values, RATES, RateTable.DEFAULT.toString());
        RateTable rates;
        try {
            rates = RateTable.parse(ratesText);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(RATES + ": " + e.getMessage(), e);
        }
        String delayText = value(values, DELAY_MS, String.valueOf(DEFAULT_DELAY_MS));
        int delayMs;
        try {
            delayMs = parseDelayMs(delayText);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(DELAY_MS + ": " + e.getMessage(), e);
        }
        String airtimeText = value(values, AIRTIME, "true");
        if (!airtimeText.equalsIgnoreCase("true") && !airtimeText.equalsIgnoreCase("false")) {
            throw refused(AIRTIME, airtimeText, "is not true or false");
        }
        LossTable loss;
        try {
            loss = LossTable.parse(value(values, LOSS, LossTable.DEFAULT.toString()));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(LOSS + ": " + e.getMessage(), e);
        }
        String queueText = value(values, QUEUE_MS, String.valueOf(DEFAULT_QUEUE_MS));
        int queueMs;
        try {
            queueMs = Integer.parseInt(queueText);
        } catch (NumberFormatException e) {
            throw refused(QUEUE_MS, queueText, "is not a whole number of milliseconds");
        }
        String queueProblem = queueProblem(queueMs);
        if (queueProblem != null) {
            throw refused(QUEUE_MS, queueText, queueProblem);
        }
        return new ShapingConfig(on, rates, delayMs, Boolean.parseBoolean(airtimeText.toLowerCase()), queueMs, loss, jitter(values));
    }

    /** The jitter keys ({@link #JITTER}, {@link #JITTER_DISTRIBUTION}, {@link #REORDER}, {@link #SEED}), each checked. */
    private static JitterConfig jitter(Map<String, String> values) {
        int ms;
        try {
            ms = parseJitterMs(value(values, JITTER, "0"));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(JITTER + ": " + e.getMessage(), e);
        }
        String distributionText = value(values, JITTER_DISTRIBUTION, JitterConfig.NONE.distribution().word());
        JitterDistribution distribution = JitterDistribution.of(distributionText);
        if (distribution == null) {
            throw refused(JITTER_DISTRIBUTION, distributionText, "is not uniform, normal, pareto or paretonormal");
        }
        String reorderText = value(values, REORDER, "false");
        if (!reorderText.equalsIgnoreCase("true") && !reorderText.equalsIgnoreCase("false")) {
            throw refused(REORDER, reorderText, "is not true or false");
        }
        String seedText = value(values, SEED, String.valueOf(JitterConfig.DEFAULT_SEED));
        long seed;
        try {
            seed = Long.parseLong(seedText);
        } catch (NumberFormatException e) {
            throw refused(SEED, seedText, "is not a whole number");
        }
        return new JitterConfig(ms, distribution, Boolean.parseBoolean(reorderText.toLowerCase()), seed);
    }

    /**
     * A delay in whole milliseconds from {@link #MIN_DELAY_MS} to {@link #MAX_DELAY_MS}, as
     * {@code wss.shaping.delayMs} and an operator's {@code FORCE ... {Delay 50}} write it;
     * whitespace around it is ignored.
     *
     * @throws IllegalArgumentException "-1 is below 0", "abc is not a whole number of milliseconds"
     */
    public static int parseDelayMs(String text) {
        return parseMs(text, MAX_DELAY_MS);
    }

    /**
     * A jitter in whole milliseconds from 0 to {@link #MAX_JITTER_MS}, as {@code wss.shaping.jitter}
     * and an operator's {@code FORCE ... {Jitter 20}} write it; the same rule as {@link #parseDelayMs}.
     */
    public static int parseJitterMs(String text) {
        return parseMs(text, MAX_JITTER_MS);
    }

    /** Whole milliseconds from 0 to {@code max}. */
    private static int parseMs(String text, int max) {
        String value = text == null ? "" : text.strip();
        if (!value.matches("[+-]?\\d+")) {
            throw new IllegalArgumentException(shown(value) + " is not a whole number of milliseconds");
        }
        long delay;
        try {
            delay = Long.parseLong(value);
        } catch (NumberFormatException e) {
            delay = value.startsWith("-") ? Long.MIN_VALUE : Long.MAX_VALUE;
        }
        String problem = outside(delay, MIN_DELAY_MS, max);
        if (problem != null) {
            throw new IllegalArgumentException(value + " " + problem);
        }
        return (int) delay;
    }

    private static String delayProblem(long delayMs) {
        return outside(delayMs, MIN_DELAY_MS, MAX_DELAY_MS);
    }

    private static String queueProblem(long queueMs) {
        return outside(queueMs, MIN_QUEUE_MS, MAX_QUEUE_MS);
    }

    /** "is below MIN", "is above MAX", or null within them. */
    private static String outside(long value, long min, long max) {
        return value < min ? "is below " + min : value > max ? "is above " + max : null;
    }

    /** The same with another loss table (the window's dialog sets the other four keys, a --config file this one). */
    public ShapingConfig withLoss(LossTable table) {
        return new ShapingConfig(on, rates, delayMs, airtime, queueMs, table, jitter);
    }

    /** The same with another seed ({@code wss.seed}: the window's dialog sets the jitter, a --config file the seed). */
    public ShapingConfig withSeed(long seed) {
        return new ShapingConfig(on, rates, delayMs, airtime, queueMs, loss, new JitterConfig(jitter.ms(), jitter.distribution(),
                jitter.reorder(), seed));
    }

    /** The percent of datagrams a pair of this strength loses: none with shaping off. */
    public double lossPercent(double dBm) {
        return on ? loss.percentFor(dBm) : 0;
    }

    private static String value(Map<String, String> values, String key, String defaultValue) {
        String value = values.get(key);
        return value == null ? defaultValue : value.strip();
    }

    private static IllegalArgumentException refused(String key, String value, String problem) {
        return new IllegalArgumentException(key + ": " + shown(value) + " " + problem);
    }

    private static String shown(String value) {
        return value.isEmpty() ? "an empty value" : value;
    }
}
