package org.usarsim.wss.gui;

import java.util.List;
import org.usarsim.wss.hub.HubSnapshot.LinkEntry;

/** "Established connections": every forwarded connection, with the WSS's outgoing port to the target. */
final class LinksPanel extends FilteredTablePanel<LinkEntry> {

    LinksPanel() {
        super("Established connections", "links", List.of(
                new RowsModel.Column<>("From", String.class, LinkEntry::from),
                new RowsModel.Column<>("To", String.class, LinkEntry::to),
                new RowsModel.Column<>("WSS Outgoing Port", Integer.class, LinkEntry::outgoingPort)));
        leastWidths(StatsPanel.NAME, StatsPanel.NAME, "65535");
    }
}
