package org.usarsim.wss.gui;

import java.util.List;
import org.usarsim.wss.hub.HubSnapshot.PortEntry;

/**
 * "Ports for incoming connections": every WSS port the hub knows, whether it listens now (a fixed
 * UDP port: whether it relays), and its kind: DNS'd, or fixed TCP or UDP (docs/fixed-ports.md).
 */
final class PortsPanel extends FilteredTablePanel<PortEntry> {

    PortsPanel() {
        super("Ports for incoming connections", "ports", List.of(
                new RowsModel.Column<>("From", String.class, PortEntry::from),
                new RowsModel.Column<>("To", String.class, PortEntry::to),
                new RowsModel.Column<>("Target Port", Integer.class, PortEntry::targetPort),
                new RowsModel.Column<>("WSS Port", Integer.class, PortEntry::wssPort),
                new RowsModel.Column<>("Listening?", String.class, port -> port.listening() ? "yes" : "no"),
                new RowsModel.Column<>("Kind", String.class, port -> port.kind().text(), "Kind",
                        "DNS: a port a robot asked for; fixed TCP or fixed UDP: made at Start from wss.fixed (docs/fixed-ports.md)")));
        leastWidths(StatsPanel.NAME, StatsPanel.NAME, "65535", "65535", "yes", "fixed UDP");
    }
}
