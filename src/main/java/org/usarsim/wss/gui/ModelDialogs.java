package org.usarsim.wss.gui;

import java.awt.Window;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.distance.SimulatorModel;

/**
 * Where the window opens a model's configuration (the built-in dialog, or the model's own), and
 * how it hands a model its stored settings.
 */
public final class ModelDialogs {

    private ModelDialogs() {
    }

    /** Whether {@link #show} has something to show for this model (what enables "Configure"). */
    public static boolean isConfigurable(PropagationModel model) {
        return model instanceof SimulatorModel || model.isConfigurable();
    }

    /**
     * Shows the model's configuration and returns when it is closed; read-only when
     * {@code editable} is false (the server runs). A {@link SimulatorModel}
     * (DistanceOnlyPropagationModel, ObstaclePropagationModel) gets {@link DistanceModelDialog}:
     * OK stores the values in {@code preferences}, under the model's {@code name()}, and hands them
     * to the model's {@code configure}. Any other model shows its own
     * {@code showConfigurationDialog(editable)}. Call on the Swing event thread.
     *
     * @return true when the built-in dialog stored new values
     */
    public static boolean show(Window owner, PropagationModel model, boolean editable, ModelPreferences preferences) {
        if (!(model instanceof SimulatorModel simulatorModel)) {
            model.showConfigurationDialog(editable);
            return false;
        }
        DistanceModelDialog dialog = new DistanceModelDialog(owner, simulatorModel, editable, preferences);
        dialog.setVisible(true);
        if (dialog.saved()) {
            configureFromPreferences(model, preferences);
        }
        return dialog.saved();
    }

    /**
     * Hands the model its stored settings (those of its {@code name()}; defaults where none is
     * stored). The window calls it before every start, so that the model runs with what the dialog
     * last stored, in this session or an earlier one.
     */
    public static void configureFromPreferences(PropagationModel model, ModelPreferences preferences) {
        model.configure(preferences.settings(model.name()));
    }
}
