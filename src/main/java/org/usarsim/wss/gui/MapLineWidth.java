package org.usarsim.wss.gui;

import org.usarsim.wss.shaping.RateTable;

/**
 * The width of a pair's line on the map: one rule, read by the painting and the legend. With links
 * shaped, a pair that is up is drawn as wide as its rate on a log scale, from {@link #THINNEST} px
 * at the default rate table's lowest rate (6 Mbit/s) to {@link #THICKEST} px at its top rate
 * (54 Mbit/s), and no thinner or thicker beyond them; a pair that is not up, and every pair with
 * links not shaped, keeps the {@link #UNSHAPED} width: its line says its state, not a rate.
 */
final class MapLineWidth {

    static final float UNSHAPED = 2.5f;
    static final float THINNEST = 1f;
    static final float THICKEST = 6f;
    /** The rates of the thinnest and the thickest line, in bit/s. */
    static final long LOWEST = RateTable.DEFAULT.lowestRate();
    static final long TOP = RateTable.DEFAULT.topRate();

    private MapLineWidth() {
    }

    /** The width of the line, in pixels. */
    static float of(MapData.Line line) {
        return line.state().isUp() && line.rate() > 0 ? forRate(line.rate()) : UNSHAPED;
    }

    /** The width of a line at this rate (bit/s, above 0), in pixels: log scale between the two ends. */
    static float forRate(long bitsPerSecond) {
        double share = Math.log((double) bitsPerSecond / LOWEST) / Math.log((double) TOP / LOWEST);
        return (float) (THINNEST + (THICKEST - THINNEST) * Math.max(0, Math.min(1, share)));
    }
}
