package org.usarsim.wss.bench;

import java.util.List;
import java.util.Locale;
import org.usarsim.wss.model.rfcomms.RfChannel;
import org.usarsim.wss.model.rfcomms.RfCommsFormulas;
import org.usarsim.wss.model.rfcomms.RfCommsTableTest;

/**
 * Prints the RFComms model's channel against RFComms' formulas at 10 distances (docs/models.md,
 * "RFComms and SubT"): the received power, the BER and the loss of a 100- and a 1500-byte message,
 * each as the model computes it, with the largest difference from the formula over the table.
 * Nothing is asserted here (RfCommsTableTest does).
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.RfCommsTable
 * </pre>
 */
public final class RfCommsTable {

    private RfCommsTable() {
    }

    public static void main(String[] args) {
        print("gz-sim's defaults (preset gz-sim)", RfChannel.GZ_SIM, RfCommsTableTest.DISTANCES);
        print("a weak radio: tx_power -30 dBm, sigma 0, the rest gz-sim's", RfCommsTableTest.WEAK, RfCommsTableTest.WEAK_DISTANCES);
    }

    private static void print(String title, RfChannel channel, List<Double> distances) {
        System.out.println(title);
        System.out.println();
        System.out.println("| distance (m) | received power (dBm) | BER | loss, 100 bytes | loss, 1500 bytes |");
        System.out.println("|---:|---:|---:|---:|---:|");
        double powerGap = 0;
        double probabilityGap = 0;
        for (double d : distances) {
            double power = channel.meanPower(d);
            double ber = channel.bitErrorRate(power);
            double formulaPower = RfCommsFormulas.power(channel.txPower(), channel.l0(), channel.fadingExponent(), channel.maxRange(), d);
            double formulaBer = RfCommsFormulas.ber(formulaPower, channel.noiseFloor());
            powerGap = Math.max(powerGap, Double.isInfinite(power) && power == formulaPower ? 0 : Math.abs(power - formulaPower));
            probabilityGap = Math.max(probabilityGap, Math.abs(ber - formulaBer));
            for (int bytes : new int[] {100, 1500}) {
                probabilityGap = Math.max(probabilityGap,
                        Math.abs(channel.lossProbability(power, bytes) - RfCommsFormulas.loss(formulaBer, bytes)));
            }
            System.out.println(String.format(Locale.ROOT, "| %s | %.2f | %.3e | %.6f | %.6f |", d, power, ber,
                    channel.lossProbability(power, 100), channel.lossProbability(power, 1500)));
        }
        System.out.println();
        System.out.println(String.format(Locale.ROOT, "largest difference from the formulas: %.2e dB, %.2e in probability",
                powerGap, probabilityGap));
        System.out.println();
    }
}
