package org.usarsim.wss.gui;

import java.awt.BorderLayout;
import java.util.List;
import java.util.stream.Collectors;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
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

    RobotsPanel() {
        super(new BorderLayout(0, 4));
        JTable table = new JTable(model);
        table.setName("robots");
        table.setRowSorter(model.sorter());
        table.setFillsViewportHeight(true);
        FilteredTablePanel.leastWidths(table, StatsPanel.NAME, "127.0.0.1", "65535,65535");
        // As wide as its columns need, no wider (Swing's default is 450 px): at the size the window
        // opens, the ports and connections beside it get the rest and show every column whole.
        int width = 0;
        for (int column = 0; column < table.getColumnCount(); column++) {
            width += table.getColumnModel().getColumn(column).getMinWidth();
        }
        table.setPreferredScrollableViewportSize(new java.awt.Dimension(width, table.getPreferredScrollableViewportSize().height));
        add(new JLabel("Connected Robots"), BorderLayout.NORTH);
        add(new JScrollPane(table), BorderLayout.CENTER);
    }

    /** Event thread. */
    void show(List<RobotEntry> robots) {
        model.setRows(robots);
    }
}
