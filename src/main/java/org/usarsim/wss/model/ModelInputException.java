package org.usarsim.wss.model;

/**
 * A model could not start because of its input, not because something is unreachable: a file its
 * settings name is missing or is not what it must be (a recording that is not one, or of another
 * version). Headless exits with 2 (bad input), as for a bad properties file; the window shows the
 * message as for any failed start.
 */
public class ModelInputException extends ModelStartException {

    public ModelInputException(String message) {
        super(message);
    }

    public ModelInputException(String message, Throwable cause) {
        super(message, cause);
    }
}
