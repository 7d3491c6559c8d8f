package org.usarsim.wss.gui;

import java.util.List;
import org.usarsim.wss.hub.HubSnapshot.PortEntry;

/** "Ports for incoming connections": every WSS port the hub knows, and whether it listens now. */
final class PortsPanel extends FilteredTablePanel<PortEntry> {

    PortsPanel() {
        super("Ports for incoming connections", "ports", List.of(
                new RowsModel.Column<>("From", String.class, PortEntry::from),
                new RowsModel.Column<>("To", String.class, PortEntry::to),
                new RowsModel.Column<>("Target Port", Integer.class, PortEntry::targetPort),
                new RowsModel.Column<>("WSS Port", Integer.class, PortEntry::wssPort),
                new RowsModel.Column<>("Listening?", String.class, port -> port.listening() ? "yes" : "no")));
        leastWidths(StatsPanel.NAME, StatsPanel.NAME, "65535", "65535", "yes");
    }
}
