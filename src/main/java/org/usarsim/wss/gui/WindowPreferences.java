package org.usarsim.wss.gui;

import java.awt.Rectangle;
import java.util.Map;
import java.util.prefs.BackingStoreException;
import java.util.logging.Logger;
import java.util.prefs.Preferences;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.protocol.ControlPort;

/**
 * What the window remembers between runs, in {@code java.util.prefs}: the port, the model, "Enable
 * Logging", "Record", the window's bounds and the "Link shaping" dialog's {@code wss.shaping*} values
 * (under their keys), under {@code org/usarsim/wss/window} (tests pass a throw-away node). The
 * models' own settings are {@link ModelPreferences}'.
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

    /** "Record" as the last start left it. */
    public boolean record() {
        return node.getBoolean("record", false);
    }

    /**
     * The link shaping values the dialog stored: each of its keys with its stored value, or
     * its default where none is stored, or where the stored one is refused (a hand-edited one,
     * with a WARNING).
     */
    public Map<String, String> shaping() {
        Map<String, String> values = ShapingValues.defaults();
        for (String key : ShapingValues.KEYS) {
            String stored = node.get(key, null);
            if (stored == null) {
                continue;
            }
            String problem = ShapingValues.problem(key, stored);
            if (problem == null) {
                values.put(key, stored.strip());
            } else {
                LOG.warning("preferences " + node.absolutePath() + ": " + key + " = '" + stored + "' is refused (" + problem
                        + "); using the default " + values.get(key));
            }
        }
        return values;
    }

    /**
     * Stores the link shaping values (stripped) and writes them out; keys not given keep what they had.
     *
     * @throws IllegalArgumentException when a key is not one of its keys or a value is refused; nothing is stored then
     * @throws BackingStoreException    when the preferences cannot be written
     */
    void storeShaping(Map<String, String> values) throws BackingStoreException {
        for (Map.Entry<String, String> entry : values.entrySet()) {
            if (!ShapingValues.KEYS.contains(entry.getKey())) {
                throw new IllegalArgumentException(entry.getKey() + " is not a link shaping setting");
            }
            String problem = ShapingValues.problem(entry.getKey(), entry.getValue());
            if (problem != null) {
                throw new IllegalArgumentException(entry.getKey() + ": " + problem);
            }
        }
        values.forEach((key, value) -> node.put(key, value.strip()));
        node.flush();
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
    void storeRun(String port, String model, boolean eventLog, boolean record) {
        node.put("port", port);
        node.put("model", model);
        node.putBoolean("eventLog", eventLog);
        node.putBoolean("record", record);
        flush();
    }

    void storeBounds(Rectangle bounds) {
        node.putInt("x", bounds.x);
        node.putInt("y", bounds.y);
        node.putInt("width", bounds.width);
        node.putInt("height", bounds.height);
        flush();
    }

    /** The monitor's URL File > Attach... last used ("" the first time). */
    public String attachUrl() {
        return node.get("attach.url", "");
    }

    /** The certificate file the last attach trusted ("" none: the JDK's trust store). */
    public String attachCert() {
        return node.get("attach.cert", "");
    }

    /** The token remembered for {@link #attachUrl} (only when the user ticked it), else null. */
    public String attachToken(String url) {
        return url.equals(attachUrl()) ? node.get("attach.token", null) : null;
    }

    /** Stores the URL and certificate of an attach; the token too when {@code remember}, else forgets any stored one. */
    void storeAttach(String url, String cert, String token, boolean remember) {
        node.put("attach.url", url);
        node.put("attach.cert", cert);
        if (remember) {
            node.put("attach.token", token);
        } else {
            node.remove("attach.token");
        }
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
