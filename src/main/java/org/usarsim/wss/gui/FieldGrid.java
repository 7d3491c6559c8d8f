package org.usarsim.wss.gui;

import java.awt.Dimension;
import java.awt.GridBagConstraints;
import java.awt.Insets;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;

/**
 * The layout of {@link DistanceModelDialog}: titled groups of fields, two to a row (label, field,
 * label, field, then a filler that takes any extra width). Fields keep their width; the labels of
 * each column get the same width in every group ({@link #alignColumns}), so the columns line up
 * from group to group.
 */
final class FieldGrid {

    private final List<JLabel> leftLabels = new ArrayList<>();
    private final List<JLabel> rightLabels = new ArrayList<>();

    /** A titled group of these labelled fields, two to a row. */
    JPanel group(String title, List<JLabel> labels, List<JTextField> fields) {
        JPanel panel = DialogParts.titled(title);
        for (int i = 0; i < fields.size(); i++) {
            int row = i / 2;
            boolean left = i % 2 == 0;
            (left ? leftLabels : rightLabels).add(labels.get(i));
            panel.add(labels.get(i), cell(left ? 0 : 2, row, left ? 0 : 18));
            panel.add(fields.get(i), cell(left ? 1 : 3, row, 6));
        }
        panel.add(new JLabel(), filler());
        return panel;
    }

    /** A label of the left column placed by its owner (it is made as wide as the others). */
    void left(JLabel label) {
        leftLabels.add(label);
    }

    /** A cell of a group's grid. */
    static GridBagConstraints cell(int x, int y, int leftInset) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = x;
        c.gridy = y;
        c.anchor = GridBagConstraints.LINE_START;
        c.insets = new Insets(3, leftInset, 3, 0);
        return c;
    }

    private static GridBagConstraints filler() {
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = 4;
        c.gridy = 0;
        c.weightx = 1;
        return c;
    }

    /** Every group gets the same label widths, so that the fields line up from group to group. */
    void alignColumns() {
        for (List<JLabel> column : List.of(leftLabels, rightLabels)) {
            int width = column.stream().mapToInt(label -> label.getPreferredSize().width).max().orElse(0);
            column.forEach(label -> label.setPreferredSize(new Dimension(width, label.getPreferredSize().height)));
        }
    }

    /** A field is never squeezed below its width (GridBagLayout falls back to minimum sizes). */
    static void keepWidth(JTextField field) {
        field.setMinimumSize(field.getPreferredSize());
    }
}
