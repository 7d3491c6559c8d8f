package org.usarsim.wss.gui;

import java.awt.Window;
import org.usarsim.wss.model.PropagationModel;

/** Where the window opens a model's configuration: the built-in dialog, or the model's own. */
public final class ModelDialogs {

    private ModelDialogs() {
    }

    /** Whether {@link #show} has something to show for this model (what enables "Configure"). */
    public static boolean isConfigurable(PropagationModel model) {
        return DistanceModelDialog.handles(model.name()) || model.isConfigurable();
    }

    /**
     * Shows the model's configuration and returns when it is closed; read-only when
     * {@code editable} is false (the server runs). DistanceOnlyPropagationModel and
     * ObstaclePropagationModel get {@link DistanceModelDialog}: OK stores the values in
     * {@code preferences} and hands them to the model's {@code configure}. Any other model shows
     * its own {@code showConfigurationDialog(editable)}. Call on the Swing event thread.
     *
     * @return true when the built-in dialog stored new values
     */
    public static boolean show(Window owner, PropagationModel model, boolean editable, ModelPreferences preferences) {
        if (!DistanceModelDialog.handles(model.name())) {
            model.showConfigurationDialog(editable);
            return false;
        }
        DistanceModelDialog dialog = new DistanceModelDialog(owner, model.name(), editable, preferences);
        dialog.setVisible(true);
        if (dialog.saved()) {
            model.configure(preferences.settings(model.name()));
        }
        return dialog.saved();
    }
}
