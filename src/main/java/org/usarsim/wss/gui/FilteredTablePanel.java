package org.usarsim.wss.gui;

import java.awt.BorderLayout;
import java.util.List;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import javax.swing.table.TableModel;
import javax.swing.table.TableRowSorter;

/**
 * A titled, sortable table with the original's filter field and "Clear" button above it (the
 * ports and the connections tables). Components are named {@code <name>}, {@code <name>Filter}
 * and {@code <name>Clear}.
 */
class FilteredTablePanel<T> extends JPanel {

    private final RowsModel<T> model;

    FilteredTablePanel(String title, String name, List<RowsModel.Column<T>> columns) {
        super(new BorderLayout(0, 4));
        model = new RowsModel<>(columns);
        JTable table = new JTable(model);
        table.setName(name);
        table.setFillsViewportHeight(true);
        TableRowSorter<TableModel> sorter = new TableRowSorter<>(model);
        table.setRowSorter(sorter);
        JTextField filter = new JTextField();
        filter.setName(name + "Filter");
        filter.getDocument().addDocumentListener(new DocumentListener() {
            @Override
            public void insertUpdate(DocumentEvent e) {
                sorter.setRowFilter(WildcardFilter.of(filter.getText()));
            }

            @Override
            public void removeUpdate(DocumentEvent e) {
                sorter.setRowFilter(WildcardFilter.of(filter.getText()));
            }

            @Override
            public void changedUpdate(DocumentEvent e) {
                sorter.setRowFilter(WildcardFilter.of(filter.getText()));
            }
        });
        JButton clear = new JButton("Clear");
        clear.setName(name + "Clear");
        clear.addActionListener(e -> filter.setText(""));
        JPanel filterRow = new JPanel(new BorderLayout(6, 0));
        filterRow.add(filter, BorderLayout.CENTER);
        filterRow.add(clear, BorderLayout.EAST);
        JPanel top = new JPanel(new BorderLayout(0, 4));
        top.add(new JLabel(title), BorderLayout.NORTH);
        top.add(filterRow, BorderLayout.SOUTH);
        add(top, BorderLayout.NORTH);
        add(new JScrollPane(table), BorderLayout.CENTER);
    }

    /** Event thread. */
    void show(List<T> rows) {
        model.setRows(rows);
    }
}
