package org.usarsim.wss.gui;

import java.awt.Color;

/** The colour of a pair's line on the map: one rule, read by the painting and the legend. */
final class MapColours {

    /** A pair whose strength is less than this above the cutoff is near it. */
    static final double NEAR_DB = 3;
    static final Color STRONG = new Color(0x2E, 0x9E, 0x3F);
    static final Color NEAR = new Color(0xE8, 0x9A, 0x00);
    static final Color BROKEN = new Color(0xA0, 0xA0, 0xA0);

    private MapColours() {
    }

    /**
     * Grey when the pair is broken or forced down; amber when up with a strength within
     * {@link #NEAR_DB} of the cutoff; green otherwise (up and strong, or up with no strength or
     * cutoff to compare).
     */
    static Color of(MapData.Line line, double cutoff) {
        if (!line.state().isUp()) {
            return BROKEN;
        }
        return line.strength() < cutoff + NEAR_DB ? NEAR : STRONG;
    }
}
