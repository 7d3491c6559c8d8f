package org.usarsim.wss.model.rfcomms;

import java.util.random.RandomGenerator;
import org.usarsim.wss.model.simulator.Shadowing;

/**
 * gz-sim's RFComms channel (src/systems/rf_comms/RFComms.cc; docs/models.md, "RFComms and SubT"),
 * its parameters with the names of its SDF elements and its formulas, matched to the letter:
 * <ul>
 * <li>received power: tx_power - (l0 + 10 fading_exponent log10(d)) dBm, -Infinity beyond
 * max_range (when max_range is above 0), drawn from a normal law of that mean whose
 * <em>variance</em> is sigma (RFComms hands sigma over as the variance: its standard deviation is
 * sqrt(sigma) dB, 3.16 dB for its default 10);</li>
 * <li>bit error rate, QPSK: erfc(sqrt(P / N)), P and N the received power and the noise floor in
 * watts (0.001 x 10^(dBm / 10));</li>
 * <li>a message of {@code bytes} bytes (bytes, not bits, as RFComms counts) lost with probability
 * 1 - (1 - BER)^bytes, written 1 - exp(bytes log1p(-BER));</li>
 * <li>capacity: bits a radio may send, and receive, in any 1 s window ({@link CapacityWindow}).</li>
 * </ul>
 * Immutable.
 */
public record RfChannel(double txPower, double noiseFloor, double l0, double fadingExponent, double sigma, double maxRange,
        double capacity) {

    /** gz-sim's defaults: 27 dBm, -90 dBm, 40 dB, 2.5, 10, 50 m, 54 Mbit/s. */
    public static final RfChannel GZ_SIM = new RfChannel(27, -90, 40, 2.5, 10, 50, 54_000_000);

    /**
     * osrf/subt's comms_model (its worlds' radio_config and range_config): 20 dBm, 1 Mbit/s, 500 m;
     * the rest as RFComms.
     */
    public static final RfChannel SUBT = new RfChannel(20, -90, 40, 2.5, 10, 500, 1_000_000);

    /** The mean received power in dBm at {@code metres}: +Infinity at 0 m, -Infinity beyond the range. */
    public double meanPower(double metres) {
        if (maxRange > 0 && metres > maxRange) {
            return Double.NEGATIVE_INFINITY;
        }
        return txPower - (l0 + 10 * fadingExponent * Math.log10(metres));
    }

    /** The standard deviation of the received power in dB at {@code metres}: sqrt(sigma), 0 beyond the range. */
    public double powerDeviation(double metres) {
        return maxRange > 0 && metres > maxRange ? 0 : Math.sqrt(sigma);
    }

    /** One draw of the received power at {@code metres}, as RFComms draws one for each message. */
    public double drawPower(double metres, RandomGenerator random) {
        double mean = meanPower(metres);
        double deviation = powerDeviation(metres);
        return deviation > 0 ? mean + deviation * Shadowing.gaussian(random) : mean;
    }

    /** The QPSK bit error rate at a received power of {@code dBm}. */
    public double bitErrorRate(double dBm) {
        return Erfc.erfc(Math.sqrt(watts(dBm) / watts(noiseFloor)));
    }

    /** The probability that a message of {@code bytes} bytes received at {@code dBm} is lost. */
    public double lossProbability(double dBm, long bytes) {
        double ber = bitErrorRate(dBm);
        return ber >= 1 ? 1 : 1 - Math.exp(bytes * Math.log1p(-ber));
    }

    /**
     * Whether a message of {@code bytes} bytes between robots {@code metres} apart is lost, as
     * RFComms decides it: the received power drawn, then a uniform draw against the loss
     * probability (kept only when the draw is above it).
     */
    public boolean lost(double metres, long bytes, RandomGenerator random) {
        double drop = lossProbability(drawPower(metres, random), bytes);
        return !(random.nextDouble() > drop);
    }

    /** dBm in watts, as RFComms converts it. */
    static double watts(double dBm) {
        return 0.001 * Math.pow(10, dBm / 10);
    }
}
