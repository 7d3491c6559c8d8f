package org.usarsim.wss.hub.core;

import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * A WSS port as the core keeps it: what it is for, its number (held by the hub's socket until the
 * port is forgotten), whether it listens, and the connections accepted on it that are still open.
 * Every time it starts listening it gets a new {@link #epoch}: a connection accepted by an older
 * listener (one a break stopped, say) is refused, whatever the port does now.
 */
public final class WssPort {

    public final PortKey key;
    public final int number;
    private final Set<Connection> links = new HashSet<>();
    /** Those of its links a step closed: done, though their sockets close after the step. */
    private final Set<Connection> cut = new HashSet<>();
    private boolean listening;
    private int epoch;

    WssPort(PortKey key, int number) {
        this.key = key;
        this.number = number;
    }

    public boolean listening() {
        return listening;
    }

    /** Which listening this is: a new number each time the port starts listening. */
    public int epoch() {
        return epoch;
    }

    void listen() {
        listening = true;
        epoch++;
    }

    /** @return true when it was listening */
    boolean stopListening() {
        boolean was = listening;
        listening = false;
        return was;
    }

    /** Whether a listener of this epoch is the one the port listens with now. */
    boolean listensWith(int listenerEpoch) {
        return listening && epoch == listenerEpoch;
    }

    void addLink(Connection link) {
        links.add(link);
    }

    void removeLink(Connection link) {
        links.remove(link);
        cut.remove(link);
    }

    /**
     * Closes its links, saying why: from this step on they are done, even before the applier
     * closes their sockets, so that none of them is announced established after it (issue 36).
     */
    void closeLinks(CloseReason reason, Changes out) {
        cut.addAll(links);
        out.close(links(), reason);
    }

    /** The hub stops: each established link said terminated, then every link closed. */
    void closeAtStop(Changes out) {
        for (Connection link : links) {
            if (link.isEstablished()) {
                out.add(new HubEvent.Terminated(key));
            }
        }
        closeLinks(CloseReason.SERVER_STOPPED, out);
    }

    /** Whether the link is committed to this port and no step has closed it since. */
    boolean carries(Connection link) {
        return links.contains(link) && !cut.contains(link);
    }

    boolean hasLinks() {
        return !links.isEmpty();
    }

    /** The open connections, a copy. */
    public List<Connection> links() {
        return List.copyOf(links);
    }

    /** Whether a connection through this port still open connects to its target from the WSS's {@code outgoingPort}. */
    boolean hasLinkFrom(int outgoingPort) {
        return links.stream().anyMatch(link -> link.outgoingPort() == outgoingPort && !link.isClosed());
    }

    @Override
    public String toString() {
        return "WSS port " + number + " (" + key + ")";
    }
}
