package org.usarsim.wss.gui;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.GridLayout;
import java.awt.Insets;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.prefs.BackingStoreException;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.KeyStroke;
import javax.swing.SwingConstants;
import javax.swing.UIManager;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import org.usarsim.wss.app.Settings;
import org.usarsim.wss.model.distance.PathLoss;
import org.usarsim.wss.model.distance.SimulatorModel;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;

/**
 * The configuration dialog of the simulator models ({@link SimulatorModel}: DistanceOnlyPropagationModel
 * and ObstaclePropagationModel), laid out as the original's (its manual's figure 2) with two
 * groups it did not have: "Link Stability" and, for an {@link ObstaclePropagationModel},
 * "Obstacles". The values are those of the model's preferences node, named by its {@code name()}. Fields hold the model keys' values as
 * text; every check is {@link Settings#problem}. The cutoff distance is derived, both ways:
 * editing Cutoff, N, Pd0 or d0 recomputes it, editing it recomputes N. OK stores the values with
 * {@link ModelPreferences}; in read-only mode (the server runs) every field is disabled and the
 * only button is Close. Modal; build and show it on the Swing event thread.
 */
final class DistanceModelDialog extends JDialog {

    /** Component names, for tests and accessibility tools; each value field is named by its key. */
    static final String CUTOFF_DISTANCE = "cutoffDistance";
    static final String RANGE_NOTE = "rangeNote";
    static final String MESSAGE = "message";
    static final String OK = "ok";
    static final String CANCEL = "cancel";
    static final String CLOSE = "close";

    /** The background of a field whose value is refused. */
    static final Color INVALID = new Color(255, 205, 205);

    private static final Color MESSAGE_COLOR = new Color(170, 0, 0);
    /** Read-only values stay readable: darker than the look and feel's pale disabled text. */
    private static final Color READ_ONLY_TEXT = new Color(90, 90, 90);

    /** A field: the key it edits, its label and what it means. */
    private record Field(String key, String label, String tip) {
    }

    private static final Field HOST = new Field("usarsim.host", "Host",
            "The machine of the simulator's position socket: a host name or an IP address");
    private static final Field PORT = new Field("usarsim.port", "Port",
            "The simulator's position port, 7435 as a rule; not 3000, which is USARSim's robot port");
    private static final Field INTERVAL = new Field("usarsim.interval", "Poll interval (ms)",
            "Milliseconds between two requests for the robots' positions (GETPOS)");
    private static final Field TIMEOUT = new Field("usarsim.timeout", "Timeout (ms)",
            "Milliseconds to wait for the simulator's answer");
    private static final Field CUTOFF = new Field("distance.cutoff", "Cutoff (dBm)",
            "Below this signal strength two robots cannot talk; -93 dBm is a property of the channel, best left as it is");
    private static final Field N = new Field("distance.n", "N",
            "The attenuation factor of the environment: how fast the signal fades with distance");
    private static final Field PD0 = new Field("distance.pd0", "Pd0 (dBm)", "The signal strength at distance d0");
    private static final Field D0 = new Field("distance.d0", "d0 (m)", "The distance at which the strength is Pd0");
    private static final Field MARGIN = new Field("distance.margin", "Margin (dB)",
            "A broken link resumes only when the strength is above Cutoff + Margin, so that a pair at the edge does not flap");
    private static final Field HOLD_TIME = new Field("distance.holdTime", "Hold time (s)",
            "A link stays broken, or resumed, at least this many seconds before it changes again");
    private static final Field ATTENUATION = new Field("obstacle.attenuation", "Attenuation per obstacle (dB)",
            "The loss for each obstacle between two robots");
    private static final Field CACHE_DISTANCE = new Field("obstacle.cacheDistance", "Cache distance (m)",
            "How far a robot moves before the obstacles between it and the others are counted again");

    private final String modelName;
    private final boolean obstacles;
    private final boolean editable;
    private final ModelPreferences preferences;

    private final Map<String, JTextField> fields = new LinkedHashMap<>();
    private final Map<String, String> labels = new LinkedHashMap<>();
    private final JTextField distance = new JTextField(10);
    private final JLabel rangeNote = new JLabel(" ");
    private final JLabel message = new JLabel(" ");
    private final List<JLabel> leftLabels = new ArrayList<>();
    private final List<JLabel> rightLabels = new ArrayList<>();
    private final Color normalBackground = distance.getBackground();

    /** True while the dialog itself sets a field's text, so that its listener does not recompute. */
    private boolean updating;
    /** What is wrong with the distance the user typed, or null. */
    private String distanceProblem;
    private boolean saved;

    /** Shows, and OK stores, the values of {@code model.name()}'s preferences; it does not touch the model itself. */
    DistanceModelDialog(Window owner, SimulatorModel model, boolean editable, ModelPreferences preferences) {
        super(owner, model.name() + " Configuration", ModalityType.APPLICATION_MODAL);
        this.modelName = model.name();
        this.obstacles = model instanceof ObstaclePropagationModel;
        this.editable = editable;
        this.preferences = preferences;
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);

        JPanel content = new JPanel(new GridBagLayout());
        content.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = 0;
        c.fill = GridBagConstraints.HORIZONTAL;
        c.weightx = 1;
        c.insets = new Insets(0, 0, 6, 0);
        content.add(group("USARSim Connection", HOST, PORT, INTERVAL, TIMEOUT), c);
        content.add(group("Signal Strength Computation Parameters", CUTOFF, N, PD0, D0), c);
        content.add(distanceGroup(), c);
        content.add(group("Link Stability", MARGIN, HOLD_TIME), c);
        if (obstacles) {
            content.add(group("Obstacles", ATTENUATION, CACHE_DISTANCE), c);
        }
        message.setName(MESSAGE);
        message.setForeground(MESSAGE_COLOR);
        message.setVerticalAlignment(SwingConstants.TOP);
        content.add(message, c);
        c.weighty = 1;
        c.anchor = GridBagConstraints.SOUTHEAST;
        c.fill = GridBagConstraints.NONE;
        c.insets = new Insets(0, 0, 0, 0);
        content.add(buttons(), c);
        setContentPane(content);
        alignColumns();

        Map<String, String> values = preferences.load(modelName);
        updating = true;
        fields.forEach((key, field) -> field.setText(values.get(key)));
        updating = false;
        showDistance();
        if (!editable) {
            fields.values().forEach(this::readOnly);
            readOnly(distance);
        }
        pack();
        // Two lines for a refusal, as wide as the dialog; the HTML text wraps within it.
        int lineHeight = message.getFontMetrics(message.getFont()).getHeight();
        message.setPreferredSize(new Dimension(10, 2 * lineHeight + 2));
        pack();
        setMinimumSize(getSize());
        setLocationRelativeTo(owner);
    }

    private void readOnly(JTextField field) {
        field.setEnabled(false);
        field.setDisabledTextColor(READ_ONLY_TEXT);
    }

    /** Whether OK stored the values. */
    boolean saved() {
        return saved;
    }

    // ---- layout ----

    /**
     * A titled group of fields, two to a row: label, field, label, field, then a filler that takes
     * any extra width. Fields keep their width, labels get the same width in every group
     * ({@link #alignColumns}), so the columns line up from group to group.
     */
    private JPanel group(String title, Field... members) {
        JPanel panel = titled(title);
        for (int i = 0; i < members.length; i++) {
            int row = i / 2;
            boolean left = i % 2 == 0;
            JTextField field = field(members[i]);
            JLabel label = label(members[i].label(), members[i].tip(), field);
            (left ? leftLabels : rightLabels).add(label);
            panel.add(label, cell(left ? 0 : 2, row, left ? 0 : 18));
            panel.add(field, cell(left ? 1 : 3, row, 6));
        }
        panel.add(new JLabel(), filler());
        return panel;
    }

    private JPanel distanceGroup() {
        JPanel panel = titled("Easy Parameter Setting by Cutoff Distance");
        String tip = "The distance at which the signal strength falls to the cutoff"
                + (obstacles ? " with no obstacle in between" : "")
                + ": d0 * 10^((Pd0 - Cutoff) / (10 N)). Editing it recomputes N.";
        distance.setName(CUTOFF_DISTANCE);
        distance.setToolTipText(tip);
        distance.getDocument().addDocumentListener(onChange(this::distanceEdited));
        JLabel label = label("Cutoff distance (m)", tip, distance);
        leftLabels.add(label);
        rangeNote.setName(RANGE_NOTE);
        panel.add(label, cell(0, 0, 0));
        panel.add(distance, cell(1, 0, 6));
        // The note takes the rest of the row and never widens it: a long one is cut, not the field.
        GridBagConstraints note = cell(2, 0, 18);
        note.gridwidth = 3;
        note.weightx = 1;
        note.fill = GridBagConstraints.HORIZONTAL;
        rangeNote.setPreferredSize(new Dimension(1, rangeNote.getPreferredSize().height));
        rangeNote.setMinimumSize(rangeNote.getPreferredSize());
        panel.add(rangeNote, note);
        keepWidth(distance);
        return panel;
    }

    private JPanel buttons() {
        JPanel panel = new JPanel(new GridLayout(1, 0, 6, 0));
        JButton cancel;
        JButton ok;
        if (editable) {
            ok = button("OK", OK);
            ok.addActionListener(e -> ok());
            cancel = button("Cancel", CANCEL);
            panel.add(ok);
            panel.add(cancel);
        } else {
            cancel = button("Close", CLOSE);
            ok = cancel;
            panel.add(cancel);
        }
        cancel.addActionListener(e -> dispose());
        getRootPane().setDefaultButton(ok);
        getRootPane().registerKeyboardAction(e -> dispose(), KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0),
                JComponent.WHEN_IN_FOCUSED_WINDOW);
        return panel;
    }

    private static JButton button(String text, String name) {
        JButton button = new JButton(text);
        button.setName(name);
        return button;
    }

    private static JPanel titled(String title) {
        JPanel panel = new JPanel(new GridBagLayout());
        panel.setBorder(BorderFactory.createCompoundBorder(BorderFactory.createTitledBorder(title),
                BorderFactory.createEmptyBorder(0, 6, 4, 6)));
        return panel;
    }

    private static GridBagConstraints cell(int x, int y, int leftInset) {
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

    private static JLabel label(String text, String tip, JComponent field) {
        JLabel label = new JLabel(text);
        label.setToolTipText(tip);
        label.setLabelFor(field);
        return label;
    }

    /** Every group gets the same label widths, so that the fields line up from group to group. */
    private void alignColumns() {
        for (List<JLabel> column : List.of(leftLabels, rightLabels)) {
            int width = column.stream().mapToInt(label -> label.getPreferredSize().width).max().orElse(0);
            column.forEach(label -> label.setPreferredSize(new Dimension(width, label.getPreferredSize().height)));
        }
    }

    private JTextField field(Field member) {
        JTextField field = new JTextField(10);
        field.setName(member.key());
        field.setToolTipText(member.tip());
        keepWidth(field);
        fields.put(member.key(), field);
        labels.put(member.key(), member.label());
        boolean parameter = member == CUTOFF || member == N || member == PD0 || member == D0;
        field.getDocument().addDocumentListener(onChange(() -> {
            mark(field, Settings.problem(member.key(), field.getText()) != null);
            if (!updating) {
                message.setText(" "); // a refusal speaks of the values OK saw; the marks stay current
                if (parameter) {
                    distanceProblem = null;
                    showDistance();
                }
            }
        }));
        return field;
    }

    /** A field is never squeezed below its width (GridBagLayout falls back to minimum sizes). */
    private static void keepWidth(JTextField field) {
        field.setMinimumSize(field.getPreferredSize());
    }

    private static DocumentListener onChange(Runnable action) {
        return new DocumentListener() {
            @Override
            public void insertUpdate(DocumentEvent e) {
                action.run();
            }

            @Override
            public void removeUpdate(DocumentEvent e) {
                action.run();
            }

            @Override
            public void changedUpdate(DocumentEvent e) {
            }
        };
    }

    private void mark(JTextField field, boolean invalid) {
        field.setBackground(invalid ? INVALID : normalBackground);
    }

    // ---- the cutoff distance, both ways ----

    /** A parameter's value, or null when its field does not hold an accepted one. */
    private Double parameter(Field member) {
        String text = fields.get(member.key()).getText();
        return Settings.problem(member.key(), text) == null ? Double.valueOf(text.strip()) : null;
    }

    /** distance = d0 * 10^((Pd0 - cutoff) / (10 N)) ({@link PathLoss#range}), shown after a parameter changed. */
    private void showDistance() {
        Double cutoff = parameter(CUTOFF);
        Double n = parameter(N);
        Double pd0 = parameter(PD0);
        Double d0 = parameter(D0);
        String text;
        String note;
        if (cutoff == null || n == null || pd0 == null || d0 == null) {
            text = "";
            note = "needs valid Cutoff, N, Pd0, d0";
        } else {
            double value = new PathLoss(pd0, n, d0, cutoff).range();
            if (Double.isInfinite(value) || value == 0) {
                // Beyond a double: 10^x overflows to infinity, or underflows to 0.
                text = value == 0 ? "0" : "unlimited";
                note = "N too small to compute a distance";
            } else {
                text = format(value);
                note = cutoff > pd0 ? "Cutoff > Pd0: within d0"
                        : cutoff.doubleValue() == pd0 ? "Cutoff = Pd0: d0, any N" : " ";
            }
        }
        updating = true;
        distance.setText(text);
        updating = false;
        mark(distance, false);
        note(note, false);
    }

    /**
     * N = (Pd0 - cutoff) / (10 log10(distance / d0)) ({@link PathLoss#exponentFor}), after the user
     * edited the distance.
     */
    private void distanceEdited() {
        if (updating) {
            return;
        }
        message.setText(" ");
        Double cutoff = parameter(CUTOFF);
        Double pd0 = parameter(PD0);
        Double d0 = parameter(D0);
        double value = parseDistance(distance.getText());
        String remark = " ";
        if (Double.isNaN(value)) {
            distanceProblem = "not a number of metres above 0";
        } else if (cutoff == null || pd0 == null || d0 == null) {
            distanceProblem = "N needs valid Cutoff, Pd0, d0";
        } else if (cutoff.doubleValue() == pd0 && value == d0) {
            // Every N gives it: N keeps its value.
            distanceProblem = null;
            remark = "Cutoff = Pd0: d0, any N";
        } else {
            double n = PathLoss.exponentFor(pd0, d0, cutoff, value);
            distanceProblem = Double.isNaN(n) ? "no N > 0 gives this distance: " + why(cutoff, pd0, d0, value) : null;
            if (distanceProblem == null) {
                updating = true;
                fields.get(N.key()).setText(format(n));
                updating = false;
            }
        }
        mark(distance, distanceProblem != null);
        note(distanceProblem == null ? remark : distanceProblem, distanceProblem != null);
        if (distanceProblem != null) {
            show(distanceRefusal()); // in full: the note beside the field is cut short
        }
    }

    private String distanceRefusal() {
        return "Cutoff distance (m): '" + distance.getText().strip() + "': " + distanceProblem;
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

    /** Beside the distance: why there is none, or what is wrong with the one typed (in red). */
    private void note(String text, boolean problem) {
        rangeNote.setText(text);
        rangeNote.setToolTipText(text.isBlank() ? null : text);
        rangeNote.setForeground(problem ? MESSAGE_COLOR : UIManager.getColor("Label.foreground"));
    }

    private static double parseDistance(String text) {
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

    // ---- OK ----

    private void ok() {
        Map<String, String> values = new LinkedHashMap<>();
        JTextField first = null;
        String refusal = null;
        int refused = 0;
        for (Map.Entry<String, JTextField> entry : fields.entrySet()) {
            String text = entry.getValue().getText().strip();
            String problem = Settings.problem(entry.getKey(), text);
            mark(entry.getValue(), problem != null);
            if (problem != null) {
                refused++;
                if (first == null) {
                    first = entry.getValue();
                    refusal = labels.get(entry.getKey()) + ": '" + text + "' is not " + problem;
                }
            }
            values.put(entry.getKey(), text);
        }
        if (distanceProblem != null) {
            refused++;
            if (first == null) {
                first = distance;
                refusal = distanceRefusal();
            }
        }
        if (first != null) {
            show(refusal + (refused > 1 ? " (and " + (refused - 1) + " more marked)" : ""));
            first.requestFocusInWindow();
            return;
        }
        try {
            preferences.store(modelName, values);
        } catch (BackingStoreException | RuntimeException e) {
            show("Cannot save the settings: " + e.getMessage());
            return;
        }
        saved = true;
        dispose();
    }

    private void show(String text) {
        message.setText("<html>" + text.replace("&", "&amp;").replace("<", "&lt;") + "</html>");
    }
}
