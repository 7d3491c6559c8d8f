package org.usarsim.wss.model.rfcomms;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The RFComms channel against RFComms' formulas, each computed by {@link RfCommsFormulas} from the
 * formula alone at 10 distances: the received power to 0.01 dB, the BER and the loss of 100- and
 * 1500-byte messages to 1e-6. {@code bench.RfCommsTable} prints the table docs/models.md shows.
 */
public class RfCommsTableTest {

    /** The distances of the table, in metres: through the default's max range of 50 m. */
    public static final List<Double> DISTANCES = List.of(1.0, 2.0, 5.0, 10.0, 20.0, 30.0, 40.0, 50.0, 50.5, 100.0);
    /** A weak radio (-30 dBm, sigma 0), so that the BER goes through its whole curve within 10 m. */
    public static final List<Double> WEAK_DISTANCES = List.of(1.0, 2.0, 3.0, 3.5, 4.0, 4.5, 5.0, 6.0, 8.0, 10.0);
    public static final RfChannel WEAK = new RfChannel(-30, -90, 40, 2.5, 0, 50, 54_000_000);

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
            double power = RfCommsFormulas.power(tx, l0, exponent, maxRange, d);
            assertEquals(power, channel.meanPower(d), 0.01, "power at " + d + " m");
            double ber = RfCommsFormulas.ber(power, noise);
            assertEquals(ber, channel.bitErrorRate(channel.meanPower(d)), 1e-6, "BER at " + d + " m");
            for (int bytes : new int[] {100, 1500}) {
                assertEquals(RfCommsFormulas.loss(ber, bytes), channel.lossProbability(channel.meanPower(d), bytes), 1e-6,
                        bytes + " bytes at " + d + " m");
            }
        }
    }
}
