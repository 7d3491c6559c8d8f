package org.usarsim.wss.model.rfcomms;

/**
 * RFComms' formulas (gz-sim src/systems/rf_comms/RFComms.cc) written out from the source for the
 * tests and the table's bench, independently of the model's classes: nothing here calls them.
 * The erfc is a numerical integral of exp(-t^2), nothing of {@link Erfc}.
 */
public final class RfCommsFormulas {

    private RfCommsFormulas() {
    }

    /** tx_power - (l0 + 10 fading_exponent log10(d)); -Infinity beyond max_range (above 0). */
    public static double power(double tx, double l0, double exponent, double maxRange, double d) {
        return maxRange > 0 && d > maxRange ? Double.NEGATIVE_INFINITY : tx - (l0 + 10 * exponent * Math.log10(d));
    }

    /** erfc(sqrt(P / N)), P and N in watts; the ratio is 10^((power - noise) / 10). */
    public static double ber(double power, double noise) {
        return erfc(Math.sqrt(Math.pow(10, (power - noise) / 10)));
    }

    /** 1 - (1 - BER)^bytes. */
    public static double loss(double ber, int bytes) {
        return 1 - Math.pow(1 - ber, bytes);
    }

    /** 2/sqrt(pi) times the integral of exp(-t^2) from x to x + 9 (the rest below 1e-35), Simpson's rule on 36,000 steps. */
    static double erfc(double x) {
        if (x > 10) {
            return 0;
        }
        int steps = 36_000;
        double h = 9.0 / steps;
        double sum = Math.exp(-x * x) + Math.exp(-(x + 9) * (x + 9));
        for (int i = 1; i < steps; i++) {
            double t = x + i * h;
            sum += (i % 2 == 1 ? 4 : 2) * Math.exp(-t * t);
        }
        return 2 / Math.sqrt(Math.PI) * sum * h / 3;
    }
}
