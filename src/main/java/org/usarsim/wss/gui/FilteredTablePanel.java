package org.usarsim.wss.gui;

import java.awt.BorderLayout;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.List;
import java.util.function.BiConsumer;
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
    private final JTable table;

    FilteredTablePanel(String title, String name, List<RowsModel.Column<T>> columns) {
        super(new BorderLayout(0, 4));
        model = new RowsModel<>(columns);
        table = new JTable(model);
        table.setName(name);
        table.setFillsViewportHeight(true);
        TableRowSorter<TableModel> sorter = model.sorter();
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

    /** Event thread: calls {@code action} with the row under a right-click (selected first) and the click. */
    void onRightClick(BiConsumer<T, MouseEvent> action) {
        table.addMouseListener(new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                popup(e);
            }

            @Override
            public void mouseReleased(MouseEvent e) {
                popup(e);
            }

            private void popup(MouseEvent e) {
                int row = table.rowAtPoint(e.getPoint());
                if (e.isPopupTrigger() && row >= 0) {
                    table.setRowSelectionInterval(row, row);
                    action.accept(model.row(table.convertRowIndexToModel(row)), e);
                }
            }
        });
    }

    /**
     * Event thread: the columns' preferred widths, in order; the table shares its width out in
     * these proportions, so that a wide column ("Last close") is not cut.
     */
    void preferredWidths(int... widths) {
        for (int i = 0; i < widths.length; i++) {
            table.getColumnModel().getColumn(i).setPreferredWidth(widths[i]);
        }
    }

    /** Event thread. */
    void show(List<T> rows) {
        model.setRows(rows);
    }
}
