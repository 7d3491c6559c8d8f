package org.usarsim.wss.gui;

import java.util.Locale;

/**
 * A robot's airtime in use (the share of the last second its radio was on the air, 0..1) as a
 * table cell shows it: "37 %", or "-" when it is not known (NaN: links not shaped, or airtime not
 * shared); sorts by the share, the unknown first.
 */
record AirtimeCell(double share) implements Comparable<AirtimeCell> {

    @Override
    public int compareTo(AirtimeCell other) {
        return Double.compare(known(), other.known());
    }

    private double known() {
        return Double.isNaN(share) ? -1 : share;
    }

    @Override
    public String toString() {
        return Double.isNaN(share) ? RateCell.NONE : String.format(Locale.ROOT, "%d %%", Math.round(share * 100));
    }
}
