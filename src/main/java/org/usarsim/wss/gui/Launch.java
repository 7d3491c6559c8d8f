package org.usarsim.wss.gui;

import java.util.Map;
import org.usarsim.wss.model.ModelSettings;

/**
 * What the command line asks of the window: a port, a model and "Enable Logging" over the stored
 * ones (null: the stored one), the model keys a --config file sets, which go over each model's
 * stored settings until its dialog stores new ones (null or empty: none), the {@code wss.shaping*}
 * keys it sets, which go over the stored link shaping until its dialog stores new values (null or
 * empty: none), whether to press Start at once, and "Record" over the stored one (null: the stored
 * one; a --config file's wss.record ticks it).
 */
public record Launch(String port, String model, Boolean eventLog, ModelSettings modelValues, Map<String, String> shapingValues,
        boolean start, Boolean record) {

    /** Nothing over the stored settings; Start not pressed. */
    public static final Launch STORED = new Launch(null, null, null, null, null, false);

    /** "Record" as stored. */
    public Launch(String port, String model, Boolean eventLog, ModelSettings modelValues, Map<String, String> shapingValues,
            boolean start) {
        this(port, model, eventLog, modelValues, shapingValues, start, null);
    }

    /** No shaping keys over the stored link shaping. */
    public Launch(String port, String model, Boolean eventLog, ModelSettings modelValues, boolean start) {
        this(port, model, eventLog, modelValues, null, start);
    }
}
