package org.usarsim.wss.protocol;

/**
 * The WSS's control port, where robots connect and speak the control protocol (docs/protocol.md):
 * its default number, written here once for the properties file (wss.port), --help and the window.
 */
public final class ControlPort {

    /** The port robots connect to unless told otherwise: the original's, 50000. */
    public static final int DEFAULT = 50000;

    private ControlPort() {
    }
}
