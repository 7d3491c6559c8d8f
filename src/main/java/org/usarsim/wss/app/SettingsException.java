package org.usarsim.wss.app;

/** A configuration the server will not run with; the message names the key and the value. */
final class SettingsException extends Exception {

    SettingsException(String message) {
        super(message);
    }
}
