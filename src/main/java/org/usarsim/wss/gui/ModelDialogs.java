package org.usarsim.wss.gui;

import java.awt.Window;
import java.util.Map;
import org.usarsim.wss.model.PropagationModel;

/**
 * Where the window opens a model's configuration (the model's own dialog, the built-in one of the
 * simulator models, or the one built from the model's declared settings), and how it hands a
 * model its stored settings.
 */
public final class ModelDialogs {

    private ModelDialogs() {
    }

    /**
     * Whether {@link #show} has something to show for this model (what enables "Configure"): a
     * dialog of its own, or declared settings.
     */
    public static boolean isConfigurable(PropagationModel model) {
        return model.isConfigurable() || !model.settings().isEmpty();
    }

    /**
     * Shows the model's configuration and returns when it is closed; read-only when
     * {@code editable} is false (the server runs). The model says which dialog, never its type:
     * in this order, a model with a dialog of its own ({@code isConfigurable()}) shows its
     * {@code showConfigurationDialog(editable)}; a model whose {@code dialogLayout()} is
     * {@code DISTANCE} or {@code DISTANCE_AND_OBSTACLES} (DistanceOnlyPropagationModel,
     * ObstaclePropagationModel) gets {@link DistanceModelDialog}, provided it declares the keys
     * that dialog shows; any other model with declared settings gets the
     * {@link GeneratedModelDialog} built from them. The built-in dialogs' OK stores the values in
     * {@code preferences}, under the model's {@code name()}, and hands them to the model's
     * {@code configure}. The built-in dialogs show the stored values. Call on the Swing event thread.
     *
     * @return true when a built-in dialog stored new values
     */
    public static boolean show(Window owner, PropagationModel model, boolean editable, ModelPreferences preferences) {
        return show(owner, model, editable, preferences, preferences.load(model));
    }

    /**
     * {@link #show(Window, PropagationModel, boolean, ModelPreferences)}, the built-in dialogs
     * showing {@code values} (a value for each key the model declares) rather than the stored ones.
     */
    static boolean show(Window owner, PropagationModel model, boolean editable, ModelPreferences preferences,
            Map<String, String> values) {
        boolean saved;
        if (model.isConfigurable()) {
            model.showConfigurationDialog(editable);
            return false;
        } else if (DistanceModelDialog.fits(model)) {
            DistanceModelDialog dialog = new DistanceModelDialog(owner, model, editable, preferences, values);
            dialog.setVisible(true);
            saved = dialog.saved();
        } else if (!model.settings().isEmpty()) {
            GeneratedModelDialog dialog = new GeneratedModelDialog(owner, model, editable, preferences, values);
            dialog.setVisible(true);
            saved = dialog.saved();
        } else {
            return false;
        }
        if (saved) {
            configureFromPreferences(model, preferences);
        }
        return saved;
    }

    /**
     * Hands the model its stored settings (those of its {@code name()}; defaults where none is
     * stored). {@link #show} calls it after an OK, on the instance the dialog showed; a run gets an
     * instance of its own, configured by the server with the values the window hands it.
     */
    public static void configureFromPreferences(PropagationModel model, ModelPreferences preferences) {
        model.configure(preferences.settingValues(model));
    }
}
