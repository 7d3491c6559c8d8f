package org.usarsim.wss.gui;

import org.usarsim.wss.model.ModelSettings;

/**
 * What the command line asks of the window: a port, a model and "Enable Logging" over the stored
 * ones (null: the stored one), the model keys a --config file sets, which go over each model's
 * stored settings until its dialog stores new ones (null or empty: none), and whether to press
 * Start at once.
 */
public record Launch(String port, String model, Boolean eventLog, ModelSettings modelValues, boolean start) {

    /** Nothing over the stored settings; Start not pressed. */
    public static final Launch STORED = new Launch(null, null, null, null, false);
}
