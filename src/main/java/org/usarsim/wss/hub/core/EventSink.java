package org.usarsim.wss.hub.core;

import java.net.InetAddress;
import java.util.logging.Level;
import org.usarsim.wss.model.WssEventListener;

/** Where the hub's events go, in order: the listeners, and the log (a line, or a WARNING a client caused). */
public interface EventSink extends WssEventListener {

    /** A line of the hub's log, limited per kind as clients' lines are (docs/reliability.md). */
    void say(Level level, String kind, String line);

    /** A WARNING a client caused, limited per client (docs/reliability.md). */
    void warn(String category, InetAddress client, String message);
}
