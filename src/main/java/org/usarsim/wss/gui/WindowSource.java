package org.usarsim.wss.gui;

import java.util.List;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.model.Replay;

/**
 * What the main window shows and steers through: the server it runs itself ({@link LocalSource})
 * or one it is attached to over the network ({@link AttachedSource}). Every method is called on
 * the event thread and returns at once: a source does its slow work on a thread of its own and
 * hands the results over in batches.
 */
interface WindowSource {

    /** A snapshot newer than the last one returned, else null. */
    HubSnapshot poll();

    /** The map gathered since the last call, else null. */
    MapData pollMap();

    /** The log lines since the last call, oldest first. */
    List<String> drainLog();

    /** The replay's controls while the server's model replays a recording, else null. */
    Replay replay();

    /** The operator's hand on a pair now, or null when there is none (no server runs). */
    PairControls controls();

    /** Whether the window offers the force menu at all (an attached window: only with an operator's token). */
    boolean offersForce();

    /** Whether Start / Stop, the port and the model and shaping dialogs are the window's own (else the server's: shown read-only). */
    boolean ownsServer();

    /** The window's title. */
    String title();

    /** A line to show above the tabs (the connection lost), or null for none. */
    String banner();

    /** The window closes: the source's threads end. */
    void close();
}
