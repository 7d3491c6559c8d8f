package org.usarsim.wss.gui;

import java.util.List;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.core.UdpCounts;

/**
 * "Link statistics": a row per pair of robots the hub has seen (docs/gui.md), from the same
 * snapshots as the other tables, with links shaped the link's rate each way ({@link RateCell});
 * a right-click on a row opens the {@link ForceMenu} of its pair.
 */
final class StatsPanel extends FilteredTablePanel<PairEntry> {

    /** The widest robot name shown whole: 12 characters. */
    static final String NAME = "Explorer1234";
    /** The widest byte count shown whole: 10 digits, grouped. */
    static final String BYTES = "9,999,999,999";
    /** The UDP counts' column, by model index. */
    private static final int UDP_COLUMN = 15;

    StatsPanel(ForceMenu forceMenu) {
        super("Link statistics", "stats", List.of(
                new RowsModel.Column<>("Robot A", String.class, PairEntry::first),
                new RowsModel.Column<>("Robot B", String.class, PairEntry::second),
                new RowsModel.Column<>("State", String.class, pair -> pair.state().text()),
                new RowsModel.Column<>("dBm", Double.class, pair -> known(pair.strength()), "dBm",
                        "The strength from A to B, as the model gives it; empty when it does not know"),
                new RowsModel.Column<>("Metres", Double.class, pair -> known(pair.distance()), "Metres",
                        "The distance between the two; empty unless the model knows both positions"),
                new RowsModel.Column<>("Bytes A>B", Long.class, PairEntry::bytesFirstToSecond, "Bytes\nA>B",
                        "Bytes forwarded from A to B since the pair was first seen"),
                new RowsModel.Column<>("Bytes B>A", Long.class, PairEntry::bytesSecondToFirst, "Bytes\nB>A",
                        "Bytes forwarded from B to A since the pair was first seen"),
                new RowsModel.Column<>("B/s A>B", Long.class, pair -> Math.round(pair.rateFirstToSecond()), "B/s\nA>B",
                        "Throughput from A to B over the last second, in bytes per second"),
                new RowsModel.Column<>("B/s B>A", Long.class, pair -> Math.round(pair.rateSecondToFirst()), "B/s\nB>A",
                        "Throughput from B to A over the last second, in bytes per second"),
                new RowsModel.Column<>("Rate A>B", RateCell.class, pair -> new RateCell(pair.linkRateFirstToSecond()), "Rate\nA>B",
                        "With links shaped, the link's rate from A to B now; - when not shaped or the pair cannot talk"),
                new RowsModel.Column<>("Rate B>A", RateCell.class, pair -> new RateCell(pair.linkRateSecondToFirst()), "Rate\nB>A",
                        "With links shaped, the link's rate from B to A now; - when not shaped or the pair cannot talk"),
                new RowsModel.Column<>("Conns", Long.class, PairEntry::connections, "Conns", "Connections established"),
                new RowsModel.Column<>("Breaks", Long.class, PairEntry::breaks, "Breaks", "Times the model broke the pair"),
                new RowsModel.Column<>("Resumes", Long.class, PairEntry::resumes, "Resumes", "Times the model resumed the pair"),
                new RowsModel.Column<>("Up %", Double.class, pair -> Math.round(pair.upShare() * 1000) / 10.0, "Up %",
                        "The share of time since first seen that the pair was up with both robots registered"),
                new RowsModel.Column<>("UDP", String.class, StatsPanel::udp, "UDP",
                        "Fixed UDP ports, A>B | B>A: datagrams sent / dropped while broken / dropped by the full queue / lost by signal"),
                new RowsModel.Column<>("Last close", String.class, pair -> pair.lastClose() == null ? "" : pair.lastClose(), "Last\nclose",
                        "Why the pair's last connection closed")));
        // Names of 12 characters, byte counts of 10 digits grouped, the longest state and close reason: whole.
        leastWidths(NAME, NAME, "forced down", "-100.0", "100.0", BYTES, BYTES, "99,999,999", "99,999,999", "54 Mbit/s",
                "54 Mbit/s", "999", "999", "999", "100.0", "0/0/0/0 | 0/0/0/0", "target refused");
        // Counts of any size: the column grows to its widest (and the table scrolls sideways) rather than cut them.
        fitsContent(UDP_COLUMN);
        onRightClick((pair, click) -> {
            javax.swing.JPopupMenu menu = forceMenu.menuFor(pair.first(), pair.second());
            if (menu != null) {
                menu.show(click.getComponent(), click.getX(), click.getY());
            }
        });
    }

    /**
     * The pair's fixed UDP ports (docs/fixed-ports.md), each way: datagrams sent/dropped broken/dropped
     * by the queue/lost to the signal, {@code 120/0/3/12 | 118/0/0/9}; empty for a pair no fixed UDP port carried.
     */
    static String udp(PairEntry pair) {
        if (pair.udpFirstToSecond().none() && pair.udpSecondToFirst().none()) {
            return "";
        }
        return counts(pair.udpFirstToSecond()) + " | " + counts(pair.udpSecondToFirst());
    }

    private static String counts(UdpCounts.Reading udp) {
        return udp.datagrams() + "/" + udp.droppedBroken() + "/" + udp.droppedQueue() + "/" + udp.lost();
    }

    /** A value the model knows; null (an empty cell, sorted first) for its NaN, "does not know". */
    private static Double known(double value) {
        return Double.isNaN(value) ? null : value;
    }
}
