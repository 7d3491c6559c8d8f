package org.usarsim.wss.gui;

import java.awt.Component;
import java.awt.FontMetrics;
import java.awt.event.MouseEvent;
import javax.swing.JLabel;
import javax.swing.JTable;
import javax.swing.table.TableColumn;
import javax.swing.table.TableColumnModel;
import javax.swing.table.TableModel;

/**
 * The window's tables: each column at least as wide as its header and as the widest text it is
 * meant to show whole ({@link #leastWidths}); the table fills its viewport while every column fits
 * at its least width and scrolls sideways when they do not, none cut. A column of texts of any
 * length (a robot's ports, the UDP counts) grows to its widest cell ({@link #fitToContent}), and a
 * cell cut all the same (a name longer than 12 characters) has its whole text as tooltip.
 * Event thread.
 */
class SidewaysTable extends JTable {

    /** Room in a header for the arrow of a sorted column. */
    private static final int SORT_ARROW = 14;
    /** Room in a cell beside its text: the renderer's border and the grid. */
    private static final int CELL_PADDING = 10;

    /** Each column's least width as {@link #leastWidths} set it, by model index: what {@link #fitToContent} never goes below. */
    private int[] least = new int[0];

    SidewaysTable(TableModel model) {
        super(model);
    }

    @Override
    public boolean getScrollableTracksViewportWidth() {
        return getParent() == null || leastWidth() <= getParent().getWidth();
    }

    /** The sum of the columns' least widths. */
    int leastWidth() {
        int sum = 0;
        for (int i = 0; i < getColumnModel().getColumnCount(); i++) {
            sum += getColumnModel().getColumn(i).getMinWidth();
        }
        return sum;
    }

    /**
     * Each column at least as wide as its header (with room for the sort arrow) and as its sample,
     * the widest text it is meant to show whole, in order ("Explorer1234" for a name of 12
     * characters).
     */
    void leastWidths(String... samples) {
        FontMetrics metrics = getFontMetrics(getFont());
        TableColumnModel columns = getColumnModel();
        least = new int[columns.getColumnCount()];
        for (int i = 0; i < columns.getColumnCount(); i++) {
            int header = getTableHeader().getDefaultRenderer()
                    .getTableCellRendererComponent(this, null, false, false, -1, i).getPreferredSize().width + SORT_ARROW;
            int content = i < samples.length ? metrics.stringWidth(samples[i]) + CELL_PADDING : 0;
            TableColumn column = columns.getColumn(i);
            least[column.getModelIndex()] = Math.max(header, content);
            column.setMinWidth(least[column.getModelIndex()]);
            column.setPreferredWidth(Math.max(column.getPreferredWidth(), column.getMinWidth()));
        }
    }

    /**
     * The column of model index {@code modelColumn} as wide as its widest cell (never below its
     * least width): after the rows changed, so that a long text scrolls sideways rather than
     * being cut.
     */
    void fitToContent(int modelColumn) {
        int width = modelColumn < least.length ? least[modelColumn] : 0;
        int shown = convertColumnIndexToView(modelColumn);
        for (int row = 0; row < getRowCount(); row++) {
            width = Math.max(width, prepareRenderer(getCellRenderer(row, shown), row, shown).getPreferredSize().width + CELL_PADDING);
        }
        TableColumn column = getColumnModel().getColumn(shown);
        if (column.getMinWidth() != width) {
            column.setMinWidth(width);
            column.setPreferredWidth(Math.max(width, column.getPreferredWidth()));
            revalidate();
        }
    }

    /** A cell's whole text when its column cuts it; otherwise what the renderer says. */
    @Override
    public String getToolTipText(MouseEvent event) {
        int row = rowAtPoint(event.getPoint());
        int column = columnAtPoint(event.getPoint());
        if (row >= 0 && column >= 0) {
            Component cell = prepareRenderer(getCellRenderer(row, column), row, column);
            if (cell instanceof JLabel label && label.getText() != null && !label.getText().isBlank()
                    && label.getPreferredSize().width > getCellRect(row, column, false).width) {
                return label.getText();
            }
        }
        return super.getToolTipText(event);
    }
}
