package org.usarsim.wss.gui;

import java.awt.Color;
import java.awt.Window;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.prefs.BackingStoreException;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;

/**
 * The configuration dialog the GUI builds for any model from its declared settings
 * ({@link PropagationModel#settings()}), with no Swing code of the model's own: a row per setting
 * with its label, a field (a check box for a boolean) named by its key, its unit, and its help as
 * the tooltip. A field whose value breaks its rule turns red as it is typed; OK checks every field
 * with the same rule and refuses with the first reason, else stores the values with
 * {@link ModelPreferences}. Read-only (the server runs): every field disabled, Close only.
 * Modal; build and show it on the Swing event thread.
 */
final class GeneratedModelDialog extends JDialog {

    private final PropagationModel model;
    private final List<Setting> declared;
    private final boolean editable;
    private final ModelPreferences preferences;

    private final Map<String, JTextField> fields = new LinkedHashMap<>();
    private final Map<String, JCheckBox> boxes = new LinkedHashMap<>();
    private final JLabel message = new JLabel(" ");
    private Color normalBackground;
    private boolean saved;

    /**
     * Shows {@code values} (a value for each key the model declares); OK stores the values in
     * {@code model.name()}'s preferences. It does not touch the model itself.
     */
    GeneratedModelDialog(Window owner, PropagationModel model, boolean editable, ModelPreferences preferences, Map<String, String> values) {
        super(owner, model.name() + " Configuration", ModalityType.APPLICATION_MODAL);
        this.model = model;
        this.declared = model.settings();
        this.editable = editable;
        this.preferences = preferences;
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);

        JPanel rows = DialogParts.titled("Settings");
        int row = 0;
        for (Setting setting : declared) {
            JComponent field = field(setting, values.get(setting.key()));
            rows.add(DialogParts.label(setting.label(), setting.help(), field), DialogParts.cell(0, row, 0, false));
            rows.add(field, DialogParts.cell(1, row, 8, false));
            if (setting.key().endsWith(".file") && field instanceof JTextField path) {
                rows.add(browse(setting, path), DialogParts.cell(2, row, 6, true));
            } else {
                JLabel unit = new JLabel(setting.unit() == null ? "" : setting.unit());
                unit.setToolTipText(setting.help());
                rows.add(unit, DialogParts.cell(2, row, 6, true));
            }
            row++;
        }

        DialogParts.layOut(this, owner, List.of(rows), message, DialogParts.buttons(this, editable, this::ok));
    }

    /** Whether OK stored the values. */
    boolean saved() {
        return saved;
    }

    private JComponent field(Setting setting, String value) {
        if (setting.type() == Setting.Type.BOOLEAN) {
            JCheckBox box = new JCheckBox();
            box.setName(setting.key());
            box.setToolTipText(setting.help());
            box.setSelected(Boolean.parseBoolean(value));
            box.setEnabled(editable);
            boxes.put(setting.key(), box);
            return box;
        }
        JTextField field = new JTextField(value, 14);
        field.setName(setting.key());
        field.setToolTipText(setting.help());
        field.setMinimumSize(field.getPreferredSize());
        normalBackground = field.getBackground();
        field.getDocument().addDocumentListener(DialogParts.onChange(() -> {
            mark(field, setting.problem(field.getText()) != null);
            message.setText(" "); // a refusal speaks of the values OK saw; the marks stay current
        }));
        mark(field, setting.problem(value) != null);
        if (!editable) {
            DialogParts.readOnly(field);
        }
        fields.put(setting.key(), field);
        return field;
    }

    /**
     * "Browse..." beside a file's field (a key ending in {@code .file}, as {@code replay.file}):
     * a file chooser from the field's folder; the file chosen goes in the field, relative to the
     * working directory when it lies under it.
     */
    private JButton browse(Setting setting, JTextField path) {
        JButton browse = new JButton("Browse...");
        browse.setName(setting.key() + "Browse");
        browse.setToolTipText("Choose the file: " + setting.help());
        browse.setEnabled(editable);
        browse.addActionListener(e -> {
            java.nio.file.Path here = java.nio.file.Path.of("").toAbsolutePath();
            javax.swing.JFileChooser chooser = new javax.swing.JFileChooser(here.toFile());
            try {
                java.nio.file.Path given = here.resolve(path.getText().strip());
                if (java.nio.file.Files.isRegularFile(given)) {
                    chooser.setSelectedFile(given.toFile());
                } else if (given.getParent() != null && java.nio.file.Files.isDirectory(given.getParent())) {
                    chooser.setCurrentDirectory(given.getParent().toFile());
                }
            } catch (java.nio.file.InvalidPathException ignored) {
                // a field that holds no path: the chooser starts in the working directory
            }
            if (chooser.showOpenDialog(this) == javax.swing.JFileChooser.APPROVE_OPTION) {
                java.nio.file.Path chosen = chooser.getSelectedFile().toPath().toAbsolutePath().normalize();
                path.setText((chosen.startsWith(here) ? here.relativize(chosen) : chosen).toString());
            }
        });
        return browse;
    }

    private void mark(JTextField field, boolean invalid) {
        field.setBackground(invalid ? DialogParts.INVALID : normalBackground);
    }

    private void ok() {
        Map<String, String> values = new LinkedHashMap<>();
        JTextField first = null;
        String refusal = null;
        int refused = 0;
        for (Setting setting : declared) {
            JCheckBox box = boxes.get(setting.key());
            if (box != null) {
                values.put(setting.key(), String.valueOf(box.isSelected()));
                continue;
            }
            JTextField field = fields.get(setting.key());
            String text = field.getText().strip();
            String problem = setting.problem(text);
            mark(field, problem != null);
            if (problem != null) {
                refused++;
                if (first == null) {
                    first = field;
                    refusal = DialogParts.refusal(setting.labelWithUnit(), text, problem);
                }
            }
            values.put(setting.key(), text);
        }
        if (first != null) {
            DialogParts.showMessage(message, refusal + (refused > 1 ? " (and " + (refused - 1) + " more marked)" : ""));
            first.requestFocusInWindow();
            return;
        }
        try {
            preferences.store(model, values);
        } catch (BackingStoreException | RuntimeException e) {
            DialogParts.showMessage(message, "Cannot save the settings: " + e.getMessage());
            return;
        }
        saved = true;
        dispose();
    }
}
