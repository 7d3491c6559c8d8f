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
import javax.swing.JTextField;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import javax.swing.table.JTableHeader;
import javax.swing.table.TableCellRenderer;
import javax.swing.table.TableModel;
import javax.swing.table.TableRowSorter;

/**
 * A titled, sortable table with the original's filter field and "Clear" button above it (the
 * ports and the connections tables). Components are named {@code <name>}, {@code <name>Filter}
 * and {@code <name>Clear}.
 */
class FilteredTablePanel<T> extends JPanel {

    private final RowsModel<T> model;
    private final SidewaysTable table;
    /** The column that grows to its widest cell, or -1. */
    private int fitted = -1;

    FilteredTablePanel(String title, String name, List<RowsModel.Column<T>> columns) {
        super(new BorderLayout(0, 4));
        model = new RowsModel<>(columns);
        table = new SidewaysTable(model);
        table.setName(name);
        table.setTableHeader(new JTableHeader(table.getColumnModel()) {
            /** As tall as its tallest header: the look measures only the first column's, one line. */
            @Override
            public java.awt.Dimension getPreferredSize() {
                java.awt.Dimension size = super.getPreferredSize();
                for (int column = 0; column < getColumnModel().getColumnCount(); column++) {
                    size.height = Math.max(size.height, getDefaultRenderer()
                            .getTableCellRendererComponent(table, null, false, false, -1, column).getPreferredSize().height);
                }
                return size;
            }

            @Override
            public String getToolTipText(MouseEvent e) {
                int column = columnAtPoint(e.getPoint());
                return column < 0 ? null : model.column(table.convertColumnIndexToModel(column)).tip();
            }
        });
        TableCellRenderer plainHeader = table.getTableHeader().getDefaultRenderer();
        table.getTableHeader().setDefaultRenderer((shown, value, selected, focused, row, column) -> plainHeader
                .getTableCellRendererComponent(shown, label(model.column(shown.convertColumnIndexToModel(column)).label()),
                        selected, focused, row, column));
        table.setDefaultRenderer(Long.class, new GroupedCount());
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

    /** Event thread: each column's least width ({@link SidewaysTable#leastWidths}). */
    void leastWidths(String... samples) {
        table.leastWidths(samples);
    }

    /** Event thread: the columns of these model indexes never wider than their least width (numbers that need no more). */
    void narrow(int... columns) {
        for (int column : columns) {
            javax.swing.table.TableColumn shown = table.getColumnModel().getColumn(table.convertColumnIndexToView(column));
            shown.setMaxWidth(shown.getMinWidth());
        }
    }

    /** Event thread: after each change of rows, the column of model index {@code column} as wide as its widest cell. */
    void fitsContent(int column) {
        this.fitted = column;
    }

    /** A header's text as the header shows it: a {@code \n} puts the rest on a second line. */
    static String label(String text) {
        if (!text.contains("\n")) {
            return text;
        }
        return "<html><center>" + text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\n", "<br>")
                + "</center></html>";
    }

    /** A count with its digits grouped (6,116,163,584), right-aligned. */
    private static final class GroupedCount extends javax.swing.table.DefaultTableCellRenderer {
        private final java.text.NumberFormat format = java.text.NumberFormat.getIntegerInstance(java.util.Locale.ROOT);

        GroupedCount() {
            setHorizontalAlignment(RIGHT);
        }

        @Override
        protected void setValue(Object value) {
            setText(value == null ? "" : format.format(value));
        }
    }

    /** Event thread. */
    void show(List<T> rows) {
        model.setRows(rows);
        if (fitted >= 0) {
            table.fitToContent(fitted);
        }
    }
}
