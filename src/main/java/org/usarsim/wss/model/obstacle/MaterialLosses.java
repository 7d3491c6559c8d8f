package org.usarsim.wss.model.obstacle;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * The loss in dB of one wall of each material crossed ({@code obstacle.loss}):
 * {@code MATERIAL:DB} separated by commas, {@code concrete:15, brick:10}. Immutable.
 */
final class MaterialLosses {

    private static final Pattern MATERIAL = Pattern.compile("[A-Za-z0-9_-]+");

    private final Map<String, Double> losses;

    private MaterialLosses(Map<String, Double> losses) {
        this.losses = Map.copyOf(losses);
    }

    /** The losses of this text; empty: none. The first mistake is the message of an IllegalArgumentException. */
    static MaterialLosses parse(String text) {
        Map<String, Double> losses = new LinkedHashMap<>();
        if (!text.isBlank()) {
            for (String part : text.split(",", -1)) {
                String row = part.strip();
                int colon = row.indexOf(':');
                String material = colon < 0 ? "" : row.substring(0, colon).strip().toLowerCase(Locale.ROOT);
                double db = colon < 0 ? Double.NaN : number(row.substring(colon + 1).strip());
                if (!MATERIAL.matcher(material).matches() || !(db >= 0) || Double.isInfinite(db)) {
                    throw new IllegalArgumentException("'" + row + "' is not MATERIAL:DB (a material is letters, digits, _"
                            + " and -; the loss a number of 0 dB or more)");
                }
                if (losses.put(material, db) != null) {
                    throw new IllegalArgumentException(material + " is given twice");
                }
            }
        }
        return new MaterialLosses(losses);
    }

    private static double number(String text) {
        try {
            return Double.parseDouble(text);
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    /** The loss of one wall of this material; null when none is given. */
    Double of(String material) {
        return losses.get(material.toLowerCase(Locale.ROOT));
    }
}
