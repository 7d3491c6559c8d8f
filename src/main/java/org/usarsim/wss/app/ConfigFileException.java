package org.usarsim.wss.app;

/**
 * A properties file (or its defaults) the server will not run with: unreadable, an unknown key, a
 * value its rule refuses; the message names the file, the key and the value.
 */
final class ConfigFileException extends Exception {

    ConfigFileException(String message) {
        super(message);
    }
}
