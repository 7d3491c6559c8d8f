package org.usarsim.wss.gui;

import java.util.UUID;
import java.util.prefs.BackingStoreException;
import java.util.prefs.Preferences;

/**
 * Throw-away preferences for tests: a node of its own directly under the user root, never the
 * user's {@code org/usarsim/wss/models}. Under Maven the user root itself is in
 * target/prefs (see the pom's surefire settings).
 */
public final class TestPreferences {

    private TestPreferences() {
    }

    public static Preferences create() {
        return Preferences.userRoot().node("wss-test-" + UUID.randomUUID());
    }

    /** Removes the node and what is under it, from memory and from disk. */
    public static void remove(Preferences root) throws BackingStoreException {
        // Written out first: the file-system store leaves the directory of a node it never wrote.
        root.flush();
        root.removeNode();
        Preferences.userRoot().flush();
    }
}
