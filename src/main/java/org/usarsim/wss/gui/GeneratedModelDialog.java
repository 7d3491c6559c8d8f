package org.usarsim.wss.gui;

import java.awt.Window;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
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
final class GeneratedModelDialog extends ModelSettingsDialog {


    private final Map<String, CheckedField> fields = new LinkedHashMap<>();
    private final Map<String, JCheckBox> boxes = new LinkedHashMap<>();

    /**
     * Shows {@code values} (a value for each key the model declares); OK stores the values in
     * {@code model.name()}'s preferences. It does not touch the model itself.
     */
    GeneratedModelDialog(Window owner, PropagationModel model, boolean editable, ModelPreferences preferences, Map<String, String> values) {
        super(owner, model, editable, preferences);
        JPanel rows = DialogParts.titled("Settings");
        int row = 0;
        for (Setting setting : declared) {
            JComponent field = field(setting, values.get(setting.key()));
            JComponent beside = setting.key().endsWith(".file") && field instanceof JTextField path ? browse(setting, path)
                    : DialogParts.unit(setting.unit() == null ? "" : setting.unit(), setting.help());
            DialogParts.row(rows, row, DialogParts.label(setting.label(), setting.help(), field), field, beside);
            row++;
        }

        DialogParts.layOut(this, owner, List.of(rows), message, DialogParts.buttons(this, editable, this::ok));
    }

    private JComponent field(Setting setting, String value) {
        if (setting.type() == Setting.Type.BOOLEAN) {
            JCheckBox box = DialogParts.checkBox(new JCheckBox(), setting.key(), setting.help(), Boolean.parseBoolean(value), editable);
            boxes.put(setting.key(), box);
            return box;
        }
        CheckedField field = new CheckedField(new JTextField(value, 14), setting.key(), setting.help(), setting::problem, message, () -> { });
        field.mark();
        if (!editable) {
            DialogParts.readOnly(field.field());
        }
        fields.put(setting.key(), field);
        return field.field();
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

    private void ok() {
        Map<String, String> values = new LinkedHashMap<>();
        Refusals refused = new Refusals();
        for (Setting setting : declared) {
            JCheckBox box = boxes.get(setting.key());
            if (box != null) {
                values.put(setting.key(), String.valueOf(box.isSelected()));
                continue;
            }
            CheckedField field = fields.get(setting.key());
            String problem = field.mark();
            if (problem != null) {
                refused.add(field.field(), DialogParts.refusal(setting.labelWithUnit(), field.text(), problem));
            }
            values.put(setting.key(), field.text());
        }
        finish(refused, values);
    }
}
