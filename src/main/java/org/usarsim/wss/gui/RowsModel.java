package org.usarsim.wss.gui;

import java.util.List;
import java.util.function.Function;
import javax.swing.table.AbstractTableModel;
import javax.swing.table.TableModel;
import javax.swing.table.TableRowSorter;

/** A table of immutable rows, replaced as a whole from the read model; only a real change repaints. */
final class RowsModel<T> extends AbstractTableModel {

    /**
     * One column: its header (its name, which a test finds it by), its type (what it sorts as), how
     * a row shows in it, what the header shows ({@code \n} breaks it onto a second line) and says
     * when pointed at (null: nothing).
     */
    record Column<T>(String header, Class<?> type, Function<T, Object> value, String label, String tip) {

        /** A column whose header shows its name, with no tip. */
        Column(String header, Class<?> type, Function<T, Object> value) {
            this(header, type, value, header, null);
        }
    }

    /** The column at this index of the model. */
    Column<T> column(int index) {
        return columns.get(index);
    }

    private final List<Column<T>> columns;
    private List<T> rows = List.of();

    RowsModel(List<Column<T>> columns) {
        this.columns = List.copyOf(columns);
    }

    /** Event thread. */
    void setRows(List<T> newRows) {
        if (!newRows.equals(rows)) {
            rows = List.copyOf(newRows);
            fireTableDataChanged();
        }
    }

    /** A sorter of this table: text columns in {@link NameOrder}, the others by their values. */
    TableRowSorter<TableModel> sorter() {
        TableRowSorter<TableModel> sorter = new TableRowSorter<>(this);
        for (int column = 0; column < columns.size(); column++) {
            if (columns.get(column).type() == String.class) {
                sorter.setComparator(column, NameOrder.INSTANCE);
            }
        }
        return sorter;
    }

    /** The row at this index of the model (not of a sorted or filtered view). */
    T row(int index) {
        return rows.get(index);
    }

    @Override
    public int getRowCount() {
        return rows.size();
    }

    @Override
    public int getColumnCount() {
        return columns.size();
    }

    @Override
    public String getColumnName(int column) {
        return columns.get(column).header();
    }

    @Override
    public Class<?> getColumnClass(int column) {
        return columns.get(column).type();
    }

    @Override
    public Object getValueAt(int row, int column) {
        return columns.get(column).value().apply(rows.get(row));
    }
}
