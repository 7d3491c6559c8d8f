package org.usarsim.wss.model;

import org.usarsim.wss.Decimals;

/**
 * The range a numeric {@link Setting} allows: a lower and an upper bound, each absent (null),
 * inclusive or exclusive; in numbers ({@link #contains}) and in words ({@link #words}).
 */
record Bounds(Double min, boolean minExclusive, Double max, boolean maxExclusive) {

    /** No bound either way. */
    static final Bounds NONE = new Bounds(null, false, null, false);

    /** These bounds with {@code minimum} as the lower one, itself allowed or not. */
    Bounds low(double minimum, boolean exclusive) {
        return new Bounds(minimum, exclusive, max, maxExclusive);
    }

    /** These bounds with {@code maximum} as the upper one, itself allowed or not. */
    Bounds high(double maximum, boolean exclusive) {
        return new Bounds(min, minExclusive, maximum, exclusive);
    }

    /** Whether the number lies within both bounds. */
    boolean contains(double number) {
        boolean low = min == null || (minExclusive ? number > min : number >= min);
        boolean high = max == null || (maxExclusive ? number < max : number <= max);
        return low && high;
    }

    /** The range in words, with a leading space or comma ("from 1 to 10", " above 0", ", 0 or more"); empty when there is none. */
    String words() {
        if (min != null && max != null && !minExclusive && !maxExclusive) {
            return " from " + Decimals.plain(min) + " to " + Decimals.plain(max);
        }
        String low = min == null ? null : minExclusive ? " above " + Decimals.plain(min) : ", " + Decimals.plain(min) + " or more";
        String high = max == null ? null : maxExclusive ? " below " + Decimals.plain(max) : ", " + Decimals.plain(max) + " or less";
        if (low != null && high != null) {
            return low + " and" + high.replaceFirst("^,", "");
        }
        return low != null ? low : high != null ? high : "";
    }
}
