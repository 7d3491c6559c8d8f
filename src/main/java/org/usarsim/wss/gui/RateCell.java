package org.usarsim.wss.gui;

import org.usarsim.wss.shaping.Bitrate;

/**
 * A link's rate one way as a table cell shows it: "54 Mbit/s" ({@link Bitrate#format}), or "-"
 * when links are not shaped or the pair cannot talk (0 bit/s); sorts by the rate, the unshaped first.
 */
record RateCell(long bitsPerSecond) implements Comparable<RateCell> {

    static final String NONE = "-";

    @Override
    public int compareTo(RateCell other) {
        return Long.compare(bitsPerSecond, other.bitsPerSecond);
    }

    @Override
    public String toString() {
        return bitsPerSecond > 0 ? Bitrate.format(bitsPerSecond) : NONE;
    }
}
