package org.usarsim.wss.gui;

import java.awt.BorderLayout;
import java.util.List;
import java.util.stream.Collectors;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import org.usarsim.wss.hub.HubSnapshot.RobotEntry;

/**
 * "Connected Robots": each registered robot's name, the address it registered from, its accepting
 * ports, and with links shaped its radio's airtime in use ({@link AirtimeCell}).
 */
final class RobotsPanel extends JPanel {

    private final RowsModel<RobotEntry> model = new RowsModel<>(List.of(
            new RowsModel.Column<>("Name", String.class, RobotEntry::name),
            new RowsModel.Column<>("IP", String.class, RobotEntry::address),
            new RowsModel.Column<>("Ports", String.class,
                    robot -> robot.ports().stream().map(String::valueOf).collect(Collectors.joining(","))),
            new RowsModel.Column<>("Airtime", AirtimeCell.class, robot -> new AirtimeCell(robot.airtime()))));

    /** The ports' column, by model index. */
    private static final int PORTS_COLUMN = 2;

    private final SidewaysTable table;

    RobotsPanel() {
        super(new BorderLayout(0, 4));
        table = new SidewaysTable(model);
        table.setName("robots");
        table.setRowSorter(model.sorter());
        table.setFillsViewportHeight(true);
        table.leastWidths(StatsPanel.NAME, "127.0.0.1", "65535,65535");
        // As wide as its columns need, no wider (Swing's default is 450 px): at the size the window
        // opens, the ports and connections beside it get the rest and show every column whole.
        table.setPreferredScrollableViewportSize(new java.awt.Dimension(table.leastWidth(),
                table.getPreferredScrollableViewportSize().height));
        add(new JLabel("Connected Robots"), BorderLayout.NORTH);
        add(new JScrollPane(table), BorderLayout.CENTER);
    }

    /** Event thread. */
    void show(List<RobotEntry> robots) {
        model.setRows(robots);
        // A robot accepting on many ports: the column grows (and the table scrolls sideways) rather than cut them.
        table.fitToContent(PORTS_COLUMN);
    }
}
