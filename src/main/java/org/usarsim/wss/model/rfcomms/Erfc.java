package org.usarsim.wss.model.rfcomms;

/**
 * The complementary error function, erfc(x) = 2/sqrt(pi) times the integral of exp(-t^2) from x
 * to infinity, which the JDK lacks: to about 1e-14 relative (the test holds it to 1e-12 against
 * known values). Below 2, one minus erf's series of positive terms, erf(x) = 2/sqrt(pi) exp(-x^2)
 * sum (2x^2)^n x / (1 3 5 ... (2n+1)) (no cancellation among its terms); from 2 on, Laplace's
 * continued fraction erfc(x) = exp(-x^2)/sqrt(pi) / (x + (1/2)/(x + 1/(x + (3/2)/(x + ...)))),
 * evaluated by the modified Lentz method; exp(-x^2) with x^2 split so that its rounding does not
 * grow with x. erfc(-x) = 2 - erfc(x).
 */
final class Erfc {

    private static final double TWO_OVER_ROOT_PI = 2 / Math.sqrt(Math.PI);
    private static final double ONE_OVER_ROOT_PI = 1 / Math.sqrt(Math.PI);
    private static final double TINY = 1e-300;
    private static final double EPSILON = 1e-16;

    private Erfc() {
    }

    static double erfc(double x) {
        if (Double.isNaN(x)) {
            return x;
        }
        if (x < 0) {
            return 2 - erfc(-x);
        }
        if (x < 2) {
            return 1 - erf(x);
        }
        if (x > 27.3) {
            return 0; // below the smallest double
        }
        return expMinusSquare(x) * ONE_OVER_ROOT_PI / continuedFraction(x);
    }

    /** erf by its series of positive terms, for 0 <= x < 2. */
    private static double erf(double x) {
        double twoSquare = 2 * x * x;
        double term = x;
        double sum = x;
        for (int n = 1; n < 200 && term > sum * EPSILON; n++) {
            term *= twoSquare / (2 * n + 1);
            sum += term;
        }
        return TWO_OVER_ROOT_PI * expMinusSquare(x) * sum;
    }

    /** x + (1/2)/(x + (2/2)/(x + (3/2)/(x + ...))), by the modified Lentz method, for x >= 2. */
    private static double continuedFraction(double x) {
        double f = x;
        double c = x;
        double d = 0;
        for (int n = 1; n < 5000; n++) {
            double a = n / 2.0;
            d = x + a * d;
            d = d == 0 ? TINY : d;
            c = x + a / c;
            c = c == 0 ? TINY : c;
            d = 1 / d;
            double delta = c * d;
            f *= delta;
            if (Math.abs(delta - 1) < EPSILON) {
                break;
            }
        }
        return f;
    }

    /** exp(-x^2), with x^2 = h^2 + (x - h)(x + h) for h = x to 16 bits after the point: h^2 exact, the rest small. */
    private static double expMinusSquare(double x) {
        double h = Math.floor(x * 65536) / 65536;
        return Math.exp(-h * h) * Math.exp(-(x - h) * (x + h));
    }
}
