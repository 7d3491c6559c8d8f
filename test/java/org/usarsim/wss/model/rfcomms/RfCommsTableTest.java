package org.usarsim.wss.model.rfcomms;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The RFComms channel against RFComms' formulas (gz-sim src/systems/rf_comms/RFComms.cc), each
 * computed here from the formula alone at 10 distances: the received power to 0.01 dB, the BER and
 * the loss of 100- and 1500-byte messages to 1e-6. The erfc here is a numerical integral of
 * exp(-t^2), nothing of {@link Erfc}. {@link #table} prints the table docs/models.md shows.
 */
class RfCommsTableTest {

    /** The distances of the table, in metres: through the default's max range of 50 m. */
    static final List<Double> DISTANCES = List.of(1.0, 2.0, 5.0, 10.0, 20.0, 30.0, 40.0, 50.0, 50.5, 100.0);
    /** A weak radio (-30 dBm), so that the BER goes through its whole curve within 10 m. */
    static final List<Double> WEAK_DISTANCES = List.of(1.0, 2.0, 3.0, 3.5, 4.0, 4.5, 5.0, 6.0, 8.0, 10.0);
    static final RfChannel WEAK = new RfChannel(-30, -90, 40, 2.5, 0, 50, 54_000_000);

    @Test
    void theGzSimPresetMatchesTheFormulas() {
        check(RfChannel.GZ_SIM, 27, -90, 40, 2.5, 50, DISTANCES);
    }

    @Test
    void theSubtPresetMatchesTheFormulas() {
        check(RfChannel.SUBT, 20, -90, 40, 2.5, 500, List.of(1.0, 5.0, 10.0, 50.0, 100.0, 200.0, 300.0, 400.0, 500.0, 501.0));
    }

    @Test
    void aWeakRadioMatchesTheFormulasAcrossTheBerCurve() {
        check(WEAK, -30, -90, 40, 2.5, 50, WEAK_DISTANCES);
    }

    @Test
    void theDefaultsAreGzSims() {
        assertEquals(new RfChannel(27, -90, 40, 2.5, 10, 50, 54e6), RfChannel.GZ_SIM);
        assertEquals(new RfChannel(20, -90, 40, 2.5, 10, 500, 1e6), RfChannel.SUBT);
    }

    private static void check(RfChannel channel, double tx, double noise, double l0, double exponent, double maxRange,
            List<Double> distances) {
        for (double d : distances) {
            double power = d > maxRange ? Double.NEGATIVE_INFINITY : tx - (l0 + 10 * exponent * Math.log10(d));
            assertEquals(power, channel.meanPower(d), 0.01, "power at " + d + " m");
            double ber = d > maxRange ? 1 : erfc(Math.sqrt(Math.pow(10, (power - noise) / 10)));
            assertEquals(ber, channel.bitErrorRate(channel.meanPower(d)), 1e-6, "BER at " + d + " m");
            for (int bytes : new int[] {100, 1500}) {
                double loss = 1 - Math.pow(1 - ber, bytes);
                assertEquals(loss, channel.lossProbability(channel.meanPower(d), bytes), 1e-6, bytes + " bytes at " + d + " m");
            }
        }
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

    /** The table docs/models.md shows: `mvn -q test -Dtest=RfCommsTableTest#table -Dwss.table=true`. */
    @Test
    void table() {
        if (!Boolean.getBoolean("wss.table")) {
            return;
        }
        print("gz-sim RFComms defaults", RfChannel.GZ_SIM, DISTANCES);
        print("a weak radio: tx_power -30 dBm, sigma 0", WEAK, WEAK_DISTANCES);
    }

    private static void print(String title, RfChannel channel, List<Double> distances) {
        System.out.println(title);
        System.out.println("| distance (m) | received power (dBm) | SNR (dB) | BER | loss, 100 bytes | loss, 1500 bytes |");
        System.out.println("|---:|---:|---:|---:|---:|---:|");
        for (double d : distances) {
            double power = channel.meanPower(d);
            System.out.printf("| %s | %.2f | %.2f | %.3e | %.6f | %.6f |%n", d, power, power - channel.noiseFloor(),
                    channel.bitErrorRate(power), channel.lossProbability(power, 100), channel.lossProbability(power, 1500));
        }
    }
}
