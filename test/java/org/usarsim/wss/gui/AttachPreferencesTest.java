package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.prefs.Preferences;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** File > Attach...'s memory: the URL and certificate always, the token only when "Remember the token" is ticked. */
class AttachPreferencesTest {

    private final Preferences root = TestPreferences.create();
    private final WindowPreferences preferences = new WindowPreferences(root.node("window"));

    @AfterEach
    void remove() throws Exception {
        TestPreferences.remove(root);
    }

    @Test
    void theTokenIsKeptOnlyWhenTickedAndOnlyForItsUrl() {
        assertEquals("", preferences.attachUrl());
        preferences.storeAttach("https://wss.lan:8443", "wss.pem", "secret", false);
        assertEquals("https://wss.lan:8443", preferences.attachUrl());
        assertEquals("wss.pem", preferences.attachCert());
        assertNull(preferences.attachToken("https://wss.lan:8443"), "unticked: in memory only");
        preferences.storeAttach("https://wss.lan:8443", "", "secret", true);
        assertEquals("secret", preferences.attachToken("https://wss.lan:8443"));
        assertNull(preferences.attachToken("https://other:8443"), "another server's token is not this one");
        preferences.storeAttach("https://wss.lan:8443", "", "secret", false);
        assertNull(preferences.attachToken("https://wss.lan:8443"), "unticked later: the stored token is forgotten");
    }
}
