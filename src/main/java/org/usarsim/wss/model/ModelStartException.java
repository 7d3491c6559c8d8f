package org.usarsim.wss.model;

/** A model could not start; the message says why, in words for the user. */
public class ModelStartException extends Exception {

    public ModelStartException(String message) {
        super(message);
    }

    public ModelStartException(String message, Throwable cause) {
        super(message, cause);
    }
}
