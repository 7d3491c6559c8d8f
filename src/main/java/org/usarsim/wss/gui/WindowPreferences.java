package org.usarsim.wss.gui;

import java.awt.Rectangle;
import java.util.prefs.BackingStoreException;
import java.util.logging.Logger;
import java.util.prefs.Preferences;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.protocol.ControlPort;

/**
 * What the window remembers between runs, in {@code java.util.prefs}: the port, the model, "Enable
 * Logging" and the window's bounds, under {@code org/usarsim/wss/window} (tests pass a throw-away
 * node). The models' own settings are {@link ModelPreferences}'.
 */
public final class WindowPreferences {

    private static final Logger LOG = Logger.getLogger(WindowPreferences.class.getName());

    private final Preferences node;

    /** The user's: {@code Preferences.userRoot().node("org/usarsim/wss/window")}. */
    public WindowPreferences() {
        this(Preferences.userRoot().node("org/usarsim/wss/window"));
    }

    public WindowPreferences(Preferences node) {
        this.node = node;
    }

    public String port() {
        return node.get("port", String.valueOf(ControlPort.DEFAULT));
    }

    public String model() {
        return node.get("model", ModelCatalog.DEFAULT_MODEL);
    }

    public boolean eventLog() {
        return node.getBoolean("eventLog", false);
    }

    /** The stored bounds, or null when none are (the first run). */
    Rectangle bounds() {
        int width = node.getInt("width", 0);
        int height = node.getInt("height", 0);
        if (width <= 0 || height <= 0) {
            return null;
        }
        return new Rectangle(node.getInt("x", 0), node.getInt("y", 0), width, height);
    }

    /** Stores what a start used. */
    void storeRun(String port, String model, boolean eventLog) {
        node.put("port", port);
        node.put("model", model);
        node.putBoolean("eventLog", eventLog);
        flush();
    }

    void storeBounds(Rectangle bounds) {
        node.putInt("x", bounds.x);
        node.putInt("y", bounds.y);
        node.putInt("width", bounds.width);
        node.putInt("height", bounds.height);
        flush();
    }

    private void flush() {
        try {
            node.flush();
        } catch (BackingStoreException e) {
            LOG.warning("could not store the window's settings: " + e.getMessage());
        }
    }
}
