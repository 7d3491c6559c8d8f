package org.usarsim.wss.monitor;

/** A monitor configuration the server will not start with (a token file others may read, a bind address without TLS): exit 2. */
public final class MonitorSetupException extends Exception {

    MonitorSetupException(String message) {
        super(message);
    }
}
