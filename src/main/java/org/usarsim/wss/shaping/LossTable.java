package org.usarsim.wss.shaping;

import org.usarsim.wss.Decimals;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

/**
 * How many datagrams a pair loses for its signal strength: rows {@code dBm:percent} from the
 * strongest signal to the weakest, as {@code wss.shaping.loss} writes them ({@code -85:1,-87:10,-90:50}).
 * A strength at or below a row's dBm loses that row's percent, the last such row counting; a
 * strength above every row loses nothing, and so does a strength the model cannot say (NaN).
 * Datagrams only: a TCP stream is never dropped by it. Empty text is the empty table (no loss).
 * Immutable; docs/shaping.md says where the default comes from.
 */
public final class LossTable {

    /** One row: a strength at or below {@code dBm} loses {@code percent} of its datagrams. */
    private record Row(double dBm, double percent) {
        @Override
        public String toString() {
            return plain(dBm) + ":" + plain(percent);
        }
    }

    /**
     * 10 % at the sensitivity of the rate table's slowest rate (-87 dBm, 6 Mbit/s: 802.11 defines a
     * receiver's sensitivity as the level with 10 % of 1000-byte frames lost), 1 % two dB above it,
     * 50 % three dB below it: the steep fall of a coded OFDM receiver's error curve.
     */
    public static final LossTable DEFAULT = parse("-85:1,-87:10,-90:50");

    /** No loss at any strength. */
    public static final LossTable NONE = new LossTable(List.of());

    private final List<Row> rows;

    private LossTable(List<Row> rows) {
        this.rows = List.copyOf(rows);
    }

    /**
     * The table {@code text} writes: comma-separated rows {@code dBm:percent}, whitespace around
     * items and around the colon ignored, dBm strictly decreasing, percent from 0 to 100; empty or
     * blank text: no rows.
     *
     * @throws IllegalArgumentException {@code "<text>": <what is wrong>}, for the caller to prefix with its key
     */
    public static LossTable parse(String text) {
        String whole = text == null ? "" : text;
        if (whole.isBlank()) {
            return NONE;
        }
        List<Row> rows = new ArrayList<>();
        for (DbmRows.Row row : DbmRows.parse(whole, "row", "percent", LossTable::percentProblem)) {
            rows.add(new Row(row.dBm(), Double.parseDouble(row.value())));
        }
        return new LossTable(rows);
    }

    private static String percentProblem(String percent) {
        return percent.matches("\\d+(\\.\\d+)?") && Double.parseDouble(percent) <= 100 ? null : "is not a percent from 0 to 100";
    }

    /** The percent of datagrams lost at a strength of {@code dBm}: the last row it is at or below; 0 above every row or for NaN. */
    public double percentFor(double dBm) {
        double percent = 0;
        if (Double.isNaN(dBm)) {
            return percent;
        }
        for (Row row : rows) {
            if (dBm <= row.dBm()) {
                percent = row.percent();
            }
        }
        return percent;
    }

    /** Whether the table has no rows. */
    public boolean isEmpty() {
        return rows.isEmpty();
    }

    /** Each row's dBm, from the strongest to the weakest (the loss benchmark pins a strength at each). */
    public List<Double> strengths() {
        return rows.stream().map(Row::dBm).toList();
    }

    /** The table as {@link #parse} reads it, canonical: {@code -85:1,-87:10,-90:50}; empty for no rows. */
    @Override
    public String toString() {
        return rows.stream().map(Row::toString).collect(Collectors.joining(","));
    }

    private static String plain(double value) {
        return Decimals.plain(BigDecimal.valueOf(value));
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof LossTable table && table.rows.equals(rows);
    }

    @Override
    public int hashCode() {
        return rows.hashCode();
    }
}
