package org.usarsim.wss.shaping;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

/**
 * The one reading of a table by signal strength, {@code dBm:value} items comma-separated from the
 * strongest signal to the weakest, shared by {@link RateTable} (steps {@code dBm:rate}) and
 * {@link LossTable} (rows {@code dBm:percent}); whitespace around items and around the colon ignored.
 */
final class DbmRows {

    /** One item as written: its strength and its value's text, stripped. */
    record Row(double dBm, String value) {
    }

    private DbmRows() {
    }

    /**
     * The items of {@code whole}, not blank.
     *
     * @param item    what an item is called ("step", "row")
     * @param value   what its value is called ("rate", "percent")
     * @param problem a value's problem, to follow it ("is not above 0"), or null when it is good
     * @throws IllegalArgumentException {@code "<text>": <what is wrong>}
     */
    static List<Row> parse(String whole, String item, String value, Function<String, String> problem) {
        String[] items = whole.split(",", -1);
        List<Row> rows = new ArrayList<>();
        for (int i = 0; i < items.length; i++) {
            String text = items[i].strip();
            String which = item + " " + (i + 1);
            if (text.isEmpty()) {
                throw refused(whole, which + " is empty");
            }
            String[] parts = text.split(":", -1);
            if (parts.length != 2) {
                throw refused(whole, which + " (" + text + ") is not dBm:" + value);
            }
            String dBm = parts[0].strip();
            String given = parts[1].strip();
            if (!dBm.matches("[+-]?\\d+(\\.\\d+)?")) {
                throw refused(whole, which + " (" + text + "): " + (dBm.isEmpty() ? "the dBm is missing" : dBm + " is not a number of dBm"));
            }
            String valueProblem = problem.apply(given);
            if (valueProblem != null) {
                throw refused(whole, which + " (" + text + "): " + (given.isEmpty() ? "the " + value + " is missing" : given + " " + valueProblem));
            }
            Row row = new Row(Double.parseDouble(dBm), given);
            if (!rows.isEmpty() && row.dBm() >= rows.get(rows.size() - 1).dBm()) {
                throw refused(whole, item + "s must go from the strongest to the weakest signal");
            }
            rows.add(row);
        }
        return rows;
    }

    static IllegalArgumentException refused(String text, String problem) {
        return new IllegalArgumentException("\"" + text + "\": " + problem);
    }
}
