package org.usarsim.wss.model.rfcomms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.DatagramLoss;
import org.usarsim.wss.model.DialogLayout;
import org.usarsim.wss.model.LinkQuality;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.simulator.ReportedRobot;

/** The RFComms and SubT models without a simulator: their declared settings, strengths, range, rate and datagram losses. */
class RfCommsModelTest {

    /** The model with positions set by the test instead of a poll. */
    private static final class Placed extends RfCommsPropagationModel {
        final Map<String, Position> at = new HashMap<>();

        @Override
        public Optional<Position> positionOf(String robot) {
            return Optional.ofNullable(at.get(robot));
        }
    }

    @Test
    void theCatalogOffersRfCommsWhoseEmptyParametersAreThePresetsInTheGeneratedDialog() {
        RfCommsPropagationModel rf = (RfCommsPropagationModel) ModelCatalog.load(RfCommsModelTest.class.getClassLoader()).find("RFComms");
        PropagationModelDefaults.check(rf.settings(), Map.of("rfcomms.preset", "gz-sim", "rfcomms.txPower", "", "rfcomms.noiseFloor", "",
                "rfcomms.l0", "", "rfcomms.fadingExponent", "", "rfcomms.sigma", "", "rfcomms.maxRange", "", "rfcomms.capacity", "",
                "distance.cutoff", "-93"));
        assertEquals(DialogLayout.GENERATED, rf.dialogLayout());
        for (String unused : List.of("distance.pd0", "distance.n", "distance.d0", "shadowing.sigma")) {
            assertEquals(null, Setting.find(rf.settings(), unused), unused);
        }
        assertEquals(RfChannel.GZ_SIM, RfCommsPropagationModel.channelOf(checked(Map.of())));
        assertEquals(RfChannel.SUBT, RfCommsPropagationModel.channelOf(checked(Map.of("rfcomms.preset", "subt"))));
        assertEquals(new RfChannel(20, -90, 40, 3, 10, 500, 1e6),
                RfCommsPropagationModel.channelOf(checked(Map.of("rfcomms.preset", "subt", "rfcomms.fadingExponent", "3"))));
    }

    @Test
    void theStrengthIsTheMeanReceivedPowerAndTheRangeStopsAtMaxRange() throws Exception {
        Placed model = new Placed();
        model.started(checked(Map.of()));
        ReportedRobot a = new ReportedRobot("A", 0, 0, 0, false);
        assertEquals(27 - 40 - 25 * Math.log10(20), model.strength(a, new ReportedRobot("B", 20, 0, 0, false), 0), 1e-9);
        assertEquals(Double.NEGATIVE_INFINITY, model.strength(a, new ReportedRobot("B", 60, 0, 0, false), 3));
        assertEquals(50, model.range(0), 1e-9);
        model.started(checked(Map.of("rfcomms.txPower", "-30")));
        assertEquals(Math.pow(10, (-30 - 40 + 93) / 25.0), model.range(0), 1e-9, "where the mean power reaches the cutoff, -93 dBm");
    }

    @Test
    void shapedTheRateIsTheCapacityAndEachWayHasOneLossRule() throws Exception {
        Placed model = new Placed();
        model.started(checked(Map.of("rfcomms.capacity", "1000000")));
        LinkQuality quality = model.linkQualityForPair("A", "B").orElseThrow();
        assertEquals(1_000_000, quality.bitsPerSecond());
        assertEquals(0, quality.delayMs());
        assertSame(quality.datagramLoss(), model.linkQualityForPair("A", "B").orElseThrow().datagramLoss(),
                "the same rule each time: the pair's condition does not change for nothing");
    }

    @Test
    void aDatagramIsLostAsRfCommsLosesItSeededByTheGenerator() throws Exception {
        Placed model = new Placed();
        model.started(checked(Map.of("rfcomms.txPower", "-30", "rfcomms.sigma", "0")));
        DatagramLoss loss = model.linkQualityForPair("A", "B").orElseThrow().datagramLoss();
        assertTrue(loss.lost(100, 0, new SplittableRandom(1)), "positions unknown: lost");
        model.at.put("A", new Position(0, 0, 0));
        model.at.put("B", new Position(4, 0, 0));
        RfChannel weak = model.channel();
        double p = weak.lossProbability(weak.meanPower(4), 100);
        assertTrue(p > 0.05 && p < 0.95, "a loss worth measuring: " + p);
        int lost = 0;
        int n = 20_000;
        for (int i = 0; i < n; i++) {
            lost += loss.lost(100, i * 1000L, new SplittableRandom(i)) ? 1 : 0;
        }
        assertEquals(p, lost / (double) n, 4 * Math.sqrt(p * (1 - p) / n), "the loss rate");
        SplittableRandom one = new SplittableRandom(7);
        SplittableRandom two = new SplittableRandom(7);
        for (int i = 0; i < 100; i++) {
            assertEquals(loss.lost(100, 0, one), loss.lost(100, 0, two), "the same seed loses the same datagrams");
        }
        Placed reseeded = new Placed();
        reseeded.started(checked(Map.of("rfcomms.txPower", "-30", "rfcomms.sigma", "0", "wss.seed", "2")));
        reseeded.at.putAll(model.at);
        DatagramLoss other = reseeded.linkQualityForPair("A", "B").orElseThrow().datagramLoss();
        SplittableRandom three = new SplittableRandom(7);
        SplittableRandom four = new SplittableRandom(7);
        int differ = 0;
        for (int i = 0; i < 100; i++) {
            differ += loss.lost(100, 0, three) != other.lost(100, 0, four) ? 1 : 0;
        }
        assertTrue(differ > 0, "another wss.seed loses other datagrams");
        model.at.put("B", new Position(51, 0, 0));
        assertTrue(loss.lost(1, 0, new SplittableRandom(3)), "beyond max range: lost");
    }

    @Test
    void theSendersCapacityWindowRefusesWhatExceedsASecondsBits() throws Exception {
        Placed model = new Placed();
        model.started(checked(Map.of("rfcomms.capacity", "8000", "rfcomms.sigma", "0")));
        model.at.put("A", new Position(0, 0, 0));
        model.at.put("B", new Position(1, 0, 0));
        model.at.put("C", new Position(0, 1, 0));
        DatagramLoss ab = model.linkQualityForPair("A", "B").orElseThrow().datagramLoss();
        DatagramLoss ac = model.linkQualityForPair("A", "C").orElseThrow().datagramLoss();
        SplittableRandom random = new SplittableRandom(1);
        assertFalse(ab.lost(600, 0, random));
        assertTrue(ac.lost(600, 1, random), "A's radio sent 600 of its 1000 bytes a second already, to B");
        assertFalse(ac.lost(400, 2, random));
        assertFalse(ab.lost(600, 1_000_000_001L, random), "a second later");
    }

    @Test
    void rfCommsSigmaIsAVarianceItsDrawsDeviateByItsSquareRoot() {
        RfChannel channel = RfChannel.GZ_SIM;
        SplittableRandom random = new SplittableRandom(11);
        int n = 40_000;
        double sum = 0;
        double squares = 0;
        for (int i = 0; i < n; i++) {
            double draw = channel.drawPower(10, random) - channel.meanPower(10);
            sum += draw;
            squares += draw * draw;
        }
        assertEquals(0, sum / n, 0.05);
        assertEquals(Math.sqrt(10), Math.sqrt(squares / n), 0.05);
    }

    private static ModelSettings checked(Map<String, String> given) {
        return new ModelSettings(Setting.checked(new RfCommsPropagationModel().settings(), given));
    }
}
