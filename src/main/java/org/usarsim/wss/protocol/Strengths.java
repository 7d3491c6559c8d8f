package org.usarsim.wss.protocol;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import org.usarsim.wss.Decimals;

/** Prints a signal strength the way the original did: C's {@code %g}, 6 significant digits. */
public final class Strengths {

    private static final int SIGNIFICANT_DIGITS = 6;

    private Strengths() {
    }

    /**
     * {@code %g} semantics: fixed notation when the decimal exponent X of the rounded value is
     * in [-4, 6), else {@code d.ddddde±XX}; trailing zeros (and a bare point) dropped. Rounding is
     * half-even on the exact binary value, as glibc does. NaN prints as {@code NaN} and the
     * infinities as {@code INF} and {@code -INF}, the tokens clients parse.
     */
    public static String format(double value) {
        if (Double.isNaN(value)) {
            return "NaN";
        }
        if (Double.isInfinite(value)) {
            return value > 0 ? "INF" : "-INF";
        }
        if (value == 0) {
            return 1 / value < 0 ? "-0" : "0";
        }
        BigDecimal rounded = new BigDecimal(value).round(new MathContext(SIGNIFICANT_DIGITS, RoundingMode.HALF_EVEN));
        int exponent = rounded.precision() - rounded.scale() - 1;
        if (exponent < -4 || exponent >= SIGNIFICANT_DIGITS) {
            String mantissa = Decimals.plain(rounded.movePointLeft(exponent));
            int magnitude = Math.abs(exponent);
            return mantissa + "e" + (exponent < 0 ? "-" : "+") + (magnitude < 10 ? "0" : "") + magnitude;
        }
        return Decimals.plain(rounded);
    }
}
