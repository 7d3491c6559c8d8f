package org.usarsim.wss.hub.tcp;

import java.io.IOException;

/** Whether a failure means this process (or the machine) has run out of descriptors. */
public final class Descriptors {

    private Descriptors() {
    }

    /** EMFILE ("Too many open files") or ENFILE ("Too many open files in system"), as the JDK words them. */
    public static boolean ranOut(IOException e) {
        String message = e.getMessage();
        return message != null && message.contains("Too many open files");
    }
}
