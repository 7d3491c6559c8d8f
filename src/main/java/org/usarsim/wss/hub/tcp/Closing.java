package org.usarsim.wss.hub.tcp;

import java.io.Closeable;
import java.io.IOException;

/** Closing what may already be closed, where a failure to close changes nothing. */
public final class Closing {

    private Closing() {
    }

    public static void quietly(Closeable closeable) {
        if (closeable == null) {
            return;
        }
        try {
            closeable.close();
        } catch (IOException ignored) {
            // Already closed or reset: nothing left to release.
        }
    }
}
