package org.usarsim.wss.gui;

import java.awt.Color;
import java.util.Map;

/** The colour of a pair's line and of a wall on the map: one rule each, read by the painting and the legend. */
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

    /** The colours of the materials of docs/models.md's defaults; a wall of none is {@link MapPainter#WALL}. */
    private static final Map<String, Color> MATERIALS = Map.of(
            "concrete", new Color(0x6E, 0x6E, 0x6E),
            "brick", new Color(0xB0, 0x4A, 0x2A),
            "drywall", new Color(0xC9, 0xA8, 0x5C),
            "wood", new Color(0x8B, 0x5A, 0x2B),
            "glass", new Color(0x3A, 0x9A, 0xD9),
            "metal", new Color(0x4A, 0x5E, 0x8A));
    /** The colours of other materials, by their name's hash. */
    private static final Color[] OTHERS = {new Color(0x8E, 0x44, 0xAD), new Color(0x16, 0xA0, 0x85), new Color(0xD3, 0x54, 0x00),
        new Color(0x7F, 0x8C, 0x1D)};

    /** A wall's colour by its material: the plain wall colour for none. */
    static Color wall(String material) {
        if (material.isEmpty()) {
            return MapPainter.WALL;
        }
        Color known = MATERIALS.get(material);
        return known != null ? known : OTHERS[Math.floorMod(material.hashCode(), OTHERS.length)];
    }
}
