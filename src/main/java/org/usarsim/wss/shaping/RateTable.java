package org.usarsim.wss.shaping;

import org.usarsim.wss.Decimals;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

/**
 * Which rate a pair's link runs at for its signal strength: steps {@code dBm:rate} from the
 * strongest signal to the weakest, as {@code wss.shaping.rates} writes them
 * ({@code -72:54M,-73:48M,...,-87:6M}). A strength at or above a step's dBm gets that step's rate
 * (the first such step); a strength below the last step keeps the last step's rate, until the
 * model breaks the pair. A strength the model cannot say (NaN) gets the lowest rate of the table.
 * Immutable.
 */
public final class RateTable {

    /** One step: a strength at or above {@code dBm} runs at {@code bitsPerSecond}. */
    private record Step(double dBm, long bitsPerSecond) {
        @Override
        public String toString() {
            return Decimals.plain(BigDecimal.valueOf(dBm)) + ":" + Bitrate.toText(bitsPerSecond);
        }
    }

    /**
     * The 802.11g receive sensitivities of a Cisco Aironet 1240AG access point's data sheet: the
     * weakest signal at which each OFDM rate is received (docs/shaping.md says where they come from).
     */
    public static final RateTable DEFAULT = parse("-72:54M,-73:48M,-77:36M,-81:24M,-83:18M,-85:12M,-86:9M,-87:6M");

    private final List<Step> steps;
    private final long lowest;

    private RateTable(List<Step> steps) {
        this.steps = List.copyOf(steps);
        this.lowest = steps.stream().mapToLong(Step::bitsPerSecond).min().orElseThrow();
    }

    /**
     * The table {@code text} writes: comma-separated steps {@code dBm:rate}, whitespace around
     * items and around the colon ignored, dBm strictly decreasing from step to step, each rate as
     * {@link Bitrate#parse} reads it.
     *
     * @throws IllegalArgumentException {@code "<text>": <what is wrong>}, for the caller to prefix with its key
     */
    public static RateTable parse(String text) {
        String whole = text == null ? "" : text;
        if (whole.isBlank()) {
            throw refused(whole, "no steps; give dBm:rate steps from the strongest signal to the weakest, e.g. -72:54M,-87:6M");
        }
        List<Step> steps = new ArrayList<>();
        for (DbmRows.Row row : DbmRows.parse(whole, "step", "rate", Bitrate::problem)) {
            steps.add(new Step(row.dBm(), Bitrate.parse(row.value())));
        }
        return new RateTable(steps);
    }

    private static IllegalArgumentException refused(String text, String problem) {
        return DbmRows.refused(text, problem);
    }

    /**
     * The rate in bit/s for a signal of {@code dBm}: the first step whose dBm it reaches, else the
     * last step's rate; the lowest rate for NaN (a model that cannot say). +Infinity (two robots in
     * the same place) reaches the first step, and so does the Noop model's 0 dBm in the default table.
     */
    public long rateFor(double dBm) {
        if (Double.isNaN(dBm)) {
            return lowest;
        }
        for (Step step : steps) {
            if (dBm >= step.dBm()) {
                return step.bitsPerSecond();
            }
        }
        return steps.get(steps.size() - 1).bitsPerSecond();
    }

    /** The lowest rate of the table, in bit/s: what a NaN strength gets. */
    public long lowestRate() {
        return lowest;
    }

    /** The first step's rate, in bit/s: what a strong signal gets. */
    public long topRate() {
        return steps.get(0).bitsPerSecond();
    }

    /** The table as {@link #parse} reads it, canonical: {@code -72:54M,-73:48M,...}. */
    @Override
    public String toString() {
        return steps.stream().map(Step::toString).collect(Collectors.joining(","));
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof RateTable table && table.steps.equals(steps);
    }

    @Override
    public int hashCode() {
        return steps.hashCode();
    }
}
