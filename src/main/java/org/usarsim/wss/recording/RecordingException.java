package org.usarsim.wss.recording;

/** A file that is not a recording this WSS can replay; the message says why in one line. */
public final class RecordingException extends Exception {

    public RecordingException(String message) {
        super(message);
    }
}
