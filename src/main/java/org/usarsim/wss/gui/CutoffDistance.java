package org.usarsim.wss.gui;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.GridBagConstraints;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.Function;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.UIManager;
import org.usarsim.wss.model.simulator.PathLoss;

/**
 * The group "Easy Parameter Setting by Cutoff Distance" of {@link DistanceModelDialog}: the
 * distance at which the signal falls to the cutoff, derived both ways. A change of Cutoff, N, Pd0
 * or d0 recomputes it ({@link #parametersChanged}); editing it recomputes N. Beside it a note says
 * why there is none, or what is wrong with the one typed. Event thread.
 */
final class CutoffDistance {

    private static final String LABEL = "Cutoff distance (m)";

    /** The parameters' keys: the dialog's fields of the model's settings. */
    static final String CUTOFF = "distance.cutoff";
    static final String N = "distance.n";
    static final String PD0 = "distance.pd0";
    static final String D0 = "distance.d0";

    private final JTextField distance = new JTextField(10);
    private final JLabel rangeNote = new JLabel(" ");
    private final Color normalBackground = distance.getBackground();
    private final Function<String, Double> parameter;
    private final Consumer<String> setN;
    private final JLabel message;

    /** True while this group sets the distance's text itself, so that its listener does not recompute N. */
    private boolean updating;
    /** What is wrong with the distance the user typed, or null. */
    private String problem;

    /**
     * The group, reading a parameter's value by key from {@code parameter} (null when its field
     * does not hold an accepted one) and giving a recomputed N to {@code setN}; a refusal is
     * shown in {@code message}.
     */
    CutoffDistance(Function<String, Double> parameter, Consumer<String> setN, JLabel message) {
        this.parameter = parameter;
        this.setN = setN;
        this.message = message;
    }

    /** The group's panel, its label joining the left column of {@code grid}; the tooltip speaks of obstacles when the model counts them. */
    JPanel panel(FieldGrid grid, boolean obstacles) {
        JPanel panel = DialogParts.titled("Easy Parameter Setting by Cutoff Distance");
        String tip = "The distance at which the signal strength falls to the cutoff"
                + (obstacles ? " with no obstacle in between" : "")
                + ": d0 * 10^((Pd0 - Cutoff) / (10 N)). Editing it recomputes N.";
        distance.setName(DistanceModelDialog.CUTOFF_DISTANCE);
        distance.setToolTipText(tip);
        distance.getDocument().addDocumentListener(DialogParts.onChange(this::edited));
        JLabel label = DialogParts.label(LABEL, tip, distance);
        grid.left(label);
        rangeNote.setName(DistanceModelDialog.RANGE_NOTE);
        panel.add(label, FieldGrid.cell(0, 0, 0));
        panel.add(distance, FieldGrid.cell(1, 0, 6));
        // The note takes the rest of the row and never widens it: two lines high, a long one wraps
        // within its width (the longest, "no N > 0 gives this distance: with Cutoff below Pd0 it
        // must be beyond d0 (2 m)", on two lines), its whole text also its tooltip.
        GridBagConstraints note = FieldGrid.cell(2, 0, 18);
        note.gridwidth = 3;
        note.weightx = 1;
        note.fill = GridBagConstraints.HORIZONTAL;
        rangeNote.setVerticalAlignment(javax.swing.SwingConstants.TOP);
        int lineHeight = rangeNote.getFontMetrics(rangeNote.getFont()).getHeight();
        rangeNote.setPreferredSize(new Dimension(1, 2 * lineHeight + 2));
        rangeNote.setMinimumSize(rangeNote.getPreferredSize());
        panel.add(rangeNote, note);
        FieldGrid.keepWidth(distance);
        return panel;
    }

    JTextField field() {
        return distance;
    }

    void readOnly() {
        DialogParts.readOnly(distance);
    }

    /** What is wrong with the distance typed, in full ("Cutoff distance (m): '5': ..."); null when nothing is. */
    String refusal() {
        return problem == null ? null : LABEL + ": '" + distance.getText().strip() + "': " + problem;
    }

    /** distance = d0 * 10^((Pd0 - cutoff) / (10 N)) ({@link PathLoss#range}), shown after a parameter changed. */
    void parametersChanged() {
        problem = null;
        Double cutoff = parameter.apply(CUTOFF);
        Double n = parameter.apply(N);
        Double pd0 = parameter.apply(PD0);
        Double d0 = parameter.apply(D0);
        String text;
        String words;
        if (cutoff == null || n == null || pd0 == null || d0 == null) {
            text = "";
            words = "needs valid Cutoff, N, Pd0, d0";
        } else {
            double value = new PathLoss(pd0, n, d0, cutoff).range();
            if (Double.isInfinite(value) || value == 0) {
                // Beyond a double: 10^x overflows to infinity, or underflows to 0.
                text = value == 0 ? "0" : "unlimited";
                words = "N too small to compute a distance";
            } else {
                text = format(value);
                words = cutoff > pd0 ? "Cutoff > Pd0: within d0"
                        : cutoff.doubleValue() == pd0 ? "Cutoff = Pd0: d0, any N" : " ";
            }
        }
        updating = true;
        distance.setText(text);
        updating = false;
        mark(false);
        note(words, false);
    }

    /**
     * N = (Pd0 - cutoff) / (10 log10(distance / d0)) ({@link PathLoss#exponentFor}), after the user
     * edited the distance.
     */
    private void edited() {
        if (updating) {
            return;
        }
        message.setText(" ");
        Double cutoff = parameter.apply(CUTOFF);
        Double pd0 = parameter.apply(PD0);
        Double d0 = parameter.apply(D0);
        double value = parse(distance.getText());
        String remark = " ";
        if (Double.isNaN(value)) {
            problem = "not a number of metres above 0";
        } else if (cutoff == null || pd0 == null || d0 == null) {
            problem = "N needs valid Cutoff, Pd0, d0";
        } else if (cutoff.doubleValue() == pd0 && value == d0) {
            // Every N gives it: N keeps its value.
            problem = null;
            remark = "Cutoff = Pd0: d0, any N";
        } else {
            double n = PathLoss.exponentFor(pd0, d0, cutoff, value);
            problem = Double.isNaN(n) ? "no N > 0 gives this distance: " + why(cutoff, pd0, d0, value) : null;
            if (problem == null) {
                setN.accept(format(n));
            }
        }
        mark(problem != null);
        note(problem == null ? remark : problem, problem != null);
        if (problem != null) {
            DialogParts.showMessage(message, refusal()); // in full: the note beside the field is cut short
        }
    }

    /** Why no N above 0 gives the distance: the sides of d0 each cutoff allows. */
    private static String why(double cutoff, double pd0, double d0, double distance) {
        String metres = format(d0) + " m";
        if (cutoff == pd0) {
            return "with Cutoff = Pd0 it is d0 (" + metres + ")";
        }
        if (distance == d0) {
            return "it is d0, which needs Cutoff = Pd0";
        }
        if (cutoff < pd0 && distance < d0) {
            return "with Cutoff below Pd0 it must be beyond d0 (" + metres + ")";
        }
        if (cutoff > pd0 && distance > d0) {
            return "with Cutoff above Pd0 it must be within d0 (" + metres + ")";
        }
        return "N too large or too small for a double";
    }

    /** Red while the distance typed is refused; else white, or grey while read-only. */
    private void mark(boolean invalid) {
        distance.setBackground(invalid ? DialogParts.INVALID : distance.isEnabled() ? normalBackground : DialogParts.readOnlyBackground());
    }

    /** Beside the distance: why there is none, or what is wrong with the one typed (in red), wrapped; its tooltip says it too. */
    private void note(String text, boolean isProblem) {
        if (text.isBlank()) {
            rangeNote.setText(text);
        } else {
            DialogParts.showMessage(rangeNote, text); // wrapped within the note's width
        }
        rangeNote.setToolTipText(text.isBlank() ? null : text);
        rangeNote.setForeground(isProblem ? DialogParts.MESSAGE_COLOR : UIManager.getColor("Label.foreground"));
    }

    private static double parse(String text) {
        try {
            double value = Double.parseDouble(text.strip());
            return Double.isFinite(value) && value > 0 ? value : Double.NaN;
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    /**
     * A computed value as the fields show it: at most four decimals, no trailing zeros, a point
     * as the decimal separator whatever the locale; exponent notation for the very large and for
     * what four decimals would show as 0.
     */
    static String format(double value) {
        double magnitude = Math.abs(value);
        if (value != 0 && (magnitude >= 1e9 || magnitude < 0.00005)) {
            return String.format(Locale.ROOT, "%.6g", value).replaceAll("\\.?0+e", "e");
        }
        String text = String.format(Locale.ROOT, "%.4f", value).replaceAll("\\.?0+$", "");
        return text.equals("-0") ? "0" : text;
    }
}
