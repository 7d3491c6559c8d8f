package org.usarsim.wss;

import java.math.BigDecimal;

/**
 * A decimal number as the project writes it everywhere a person or a file reads one: its digits
 * plainly, no exponent, no trailing zeros ({@code 0.25}, {@code 4}, {@code 1000000}, {@code -49.67}).
 * The one place of that rule: settings' ranges, speeds, strengths, times of a recording, rate and
 * loss tables.
 */
public final class Decimals {

    private Decimals() {
    }

    /** {@code 2.50} as {@code 2.5}, {@code 1E+3} as {@code 1000}, {@code 0.000} as {@code 0}. */
    public static String plain(BigDecimal number) {
        return number.stripTrailingZeros().toPlainString();
    }

    /** The shortest decimal that reads back as this double ({@link BigDecimal#valueOf(double)}), plainly: {@code 0.25}, {@code 4}. */
    public static String plain(double value) {
        return plain(BigDecimal.valueOf(value));
    }
}
