package org.usarsim.wss.hub.tcp;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Logger;

/**
 * The listening sockets one step of the hub stops: collected while its port work is applied,
 * handed to the {@link PortSelector}'s thread at once, and waited for once ({@link #await}), so a
 * robot that drives out of range of a hundred others costs one wake-up of that thread, not a
 * hundred. Used by one thread.
 */
public final class Closes {

    private static final Logger LOG = Logger.getLogger(Closes.class.getName());

    private final PortSelector selector;
    private final List<PortListener> added = new ArrayList<>();

    Closes(PortSelector selector) {
        this.selector = selector;
    }

    void add(PortListener listener) {
        added.add(listener);
    }

    /** Returns once every listener added is closed for real: a connect to its port is refused. */
    public void await() {
        if (added.isEmpty()) {
            return;
        }
        List<PortListener> closing = List.copyOf(added);
        added.clear();
        selector.close(closing);
        long deadline = selector.clock().nanoTime() + PortSelector.CLOSE_WAIT_NS;
        for (PortListener listener : closing) {
            if (!listener.awaitClosed(deadline)) {
                LOG.severe(listener.port + ": its listening socket was not closed in time");
            }
        }
    }
}
