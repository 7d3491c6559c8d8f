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

    StatsPanel(ForceMenu forceMenu) {
        super("Link statistics", "stats", List.of(
                new RowsModel.Column<>("Robot A", String.class, PairEntry::first),
                new RowsModel.Column<>("Robot B", String.class, PairEntry::second),
                new RowsModel.Column<>("State", String.class, pair -> pair.state().text()),
                new RowsModel.Column<>("dBm", Double.class, pair -> known(pair.strength())),
                new RowsModel.Column<>("Metres", Double.class, pair -> known(pair.distance())),
                new RowsModel.Column<>("Bytes A>B", Long.class, PairEntry::bytesFirstToSecond),
                new RowsModel.Column<>("Bytes B>A", Long.class, PairEntry::bytesSecondToFirst),
                new RowsModel.Column<>("B/s A>B", Long.class, pair -> Math.round(pair.rateFirstToSecond())),
                new RowsModel.Column<>("B/s B>A", Long.class, pair -> Math.round(pair.rateSecondToFirst())),
                new RowsModel.Column<>("Rate A>B", RateCell.class, pair -> new RateCell(pair.linkRateFirstToSecond())),
                new RowsModel.Column<>("Rate B>A", RateCell.class, pair -> new RateCell(pair.linkRateSecondToFirst())),
                new RowsModel.Column<>("Conns", Long.class, PairEntry::connections),
                new RowsModel.Column<>("Breaks", Long.class, PairEntry::breaks),
                new RowsModel.Column<>("Resumes", Long.class, PairEntry::resumes),
                new RowsModel.Column<>("Up %", Double.class, pair -> Math.round(pair.upShare() * 1000) / 10.0),
                new RowsModel.Column<>("UDP", String.class, StatsPanel::udp),
                new RowsModel.Column<>("Last close", String.class, pair -> pair.lastClose() == null ? "" : pair.lastClose())));
        // Robot A, Robot B, State, dBm, Metres, Bytes x2, B/s x2, Rate x2, Conns, Breaks, Resumes, Up %, UDP, Last close
        preferredWidths(57, 57, 75, 60, 52, 78, 78, 60, 60, 70, 70, 50, 55, 70, 45, 30, 118);
        onRightClick((pair, click) -> forceMenu.menuFor(pair.first(), pair.second())
                .show(click.getComponent(), click.getX(), click.getY()));
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
