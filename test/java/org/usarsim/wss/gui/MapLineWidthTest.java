package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.HubSnapshot.RobotEntry;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/** The width of a pair's line on the map, by its rate (a pure rule), and what the line's label says. */
class MapLineWidthTest {

    @Test
    void oneToSixPixelsFromTheDefaultTablesLowestRateToItsTopOnALogScale() {
        assertEquals(6_000_000, MapLineWidth.LOWEST);
        assertEquals(54_000_000, MapLineWidth.TOP);
        assertEquals(1f, MapLineWidth.forRate(6_000_000), 1e-6);
        assertEquals(6f, MapLineWidth.forRate(54_000_000), 1e-6);
        assertEquals(3.5f, MapLineWidth.forRate(18_000_000), 1e-6, "18 is 6 x 3 and 54 is 6 x 9: halfway on a log scale");
        assertEquals(1f, MapLineWidth.forRate(1_000_000), 1e-6, "below the lowest: the thinnest");
        assertEquals(1f, MapLineWidth.forRate(1), 1e-6);
        assertEquals(6f, MapLineWidth.forRate(1_000_000_000), 1e-6, "above the top: the thickest");
        float before = 0;
        for (long mbits : new long[] {6, 9, 12, 18, 24, 36, 48, 54}) {
            float width = MapLineWidth.forRate(mbits * 1_000_000);
            assertTrue(width > before, mbits + " Mbit/s is wider than the rate below it: " + width + " after " + before);
            before = width;
        }
    }

    @Test
    void aPairThatIsUpIsAsWideAsItsRateAndAnyOtherLineAsWideAsUnshaped() {
        assertEquals(6f, MapLineWidth.of(line(PairState.UP, 54_000_000)), 1e-6);
        assertEquals(3.5f, MapLineWidth.of(line(PairState.FORCED_UP, 18_000_000)), 1e-6, "forced up: its (pinned) rate");
        assertEquals(MapLineWidth.UNSHAPED, MapLineWidth.of(line(PairState.UP, 0)), "links not shaped: today's width");
        assertEquals(MapLineWidth.UNSHAPED, MapLineWidth.of(line(PairState.BROKEN, 54_000_000)), "broken: no rate to show");
        assertEquals(MapLineWidth.UNSHAPED, MapLineWidth.of(line(PairState.FORCED_DOWN, 6_000_000)));
        assertEquals(2.5f, MapLineWidth.UNSHAPED);
    }

    @Test
    void aPairsRateIsTheSlowerWaysOrTheOneKnown() {
        assertEquals(12_000_000, MapData.rateOf(pair(54_000_000, 12_000_000)));
        assertEquals(12_000_000, MapData.rateOf(pair(12_000_000, 54_000_000)));
        assertEquals(6_000_000, MapData.rateOf(pair(0, 6_000_000)));
        assertEquals(6_000_000, MapData.rateOf(pair(6_000_000, 0)));
        assertEquals(0, MapData.rateOf(pair(0, 0)), "not shaped");
    }

    @Test
    void theLabelSaysTheStrengthAndTheRateOfAPairThatIsUpOrTheStateOfOneThatIsNot() {
        assertEquals("-71.3 dBm, 54 Mbit/s", MapPainter.lineLabel(new MapData.Line("A", "B", PairState.UP, -71.26, 54_000_000)));
        assertEquals("-71.3 dBm", MapPainter.lineLabel(new MapData.Line("A", "B", PairState.UP, -71.26, 0)), "not shaped");
        assertEquals("-95.0 dBm, broken", MapPainter.lineLabel(new MapData.Line("A", "B", PairState.BROKEN, -95, 6_000_000)));
        assertEquals("-60.0 dBm, forced down", MapPainter.lineLabel(new MapData.Line("A", "B", PairState.FORCED_DOWN, -60, 0)));
        assertEquals("broken", MapPainter.lineLabel(new MapData.Line("A", "B", PairState.BROKEN, Double.NaN, 0)));
        assertEquals("1.5 Mbit/s", MapPainter.lineLabel(new MapData.Line("A", "B", PairState.FORCED_UP, Double.NaN, 1_500_000)));
        assertEquals("", MapPainter.lineLabel(new MapData.Line("A", "B", PairState.UP, Double.POSITIVE_INFINITY, 0)));
    }

    private static MapData.Line line(PairState state, long rate) {
        return new MapData.Line("A", "B", state, -60, rate);
    }

    private static PairEntry pair(long firstToSecond, long secondToFirst) {
        return new PairEntry("A", "B", PairState.UP, -60, 5, 0, 0, 0, 0, 0, 0, 0, 1, null, firstToSecond, secondToFirst);
    }

    @Test
    void theMapTakesEachSeenPairsRateFromTheSnapshot() {
        HubSnapshot snapshot = new HubSnapshot(List.of(new RobotEntry("A", "127.0.0.2", List.of()),
                new RobotEntry("B", "127.0.0.3", List.of()), new RobotEntry("C", "127.0.0.4", List.of())), List.of(), List.of(),
                List.of(pair(24_000_000, 24_000_000)));
        MapData map = MapData.gather(snapshot, new NoopPropagationModel());
        assertEquals(List.of("A-B 24000000", "A-C 0", "B-C 0"),
                map.lines().stream().map(line -> line.first() + "-" + line.second() + " " + line.rate()).toList(),
                "a pair the hub has not seen has no rate yet");
    }
}
