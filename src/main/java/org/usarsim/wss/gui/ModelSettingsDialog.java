package org.usarsim.wss.gui;

import java.awt.Window;
import java.util.List;
import java.util.Map;
import javax.swing.JDialog;
import javax.swing.JLabel;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;

/**
 * What the two dialogs of a model's settings share ({@link DistanceModelDialog},
 * {@link GeneratedModelDialog}): the model and its declaration, whether it may be edited, its
 * preferences, the message under the fields, and OK's end: a refusal said, or the values stored
 * in the model's preferences and the dialog closed. Modal; event thread.
 */
abstract class ModelSettingsDialog extends JDialog {

    final PropagationModel model;
    final List<Setting> declared;
    final boolean editable;
    final JLabel message = new JLabel(" ");
    private final ModelPreferences preferences;
    private boolean saved;

    /** "NAME Configuration", closed by disposing of it; OK stores in {@code model.name()}'s preferences, never in the model itself. */
    ModelSettingsDialog(Window owner, PropagationModel model, boolean editable, ModelPreferences preferences) {
        super(owner, model.name() + " Configuration", ModalityType.APPLICATION_MODAL);
        this.model = model;
        this.declared = model.settings();
        this.editable = editable;
        this.preferences = preferences;
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
    }

    /** Whether OK stored the values. */
    boolean saved() {
        return saved;
    }

    /** OK's end: the first refusal said (the dialog stays open), else the values stored and the dialog closed. */
    void finish(Refusals refused, Map<String, String> values) {
        if (refused.show(message) || !DialogParts.stored(message, () -> preferences.store(model, values))) {
            return;
        }
        saved = true;
        dispose();
    }
}
