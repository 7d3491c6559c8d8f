package org.usarsim.wss.hub.udp;

import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A fixed UDP port's senders (docs/fixed-ports.md): each sender (address and port) has a session,
 * its own socket of the WSS toward the target, so that the target's answers to that socket go back
 * to that sender. A session expires once nothing passed either way for the idle time. Pure: the
 * time is given (the hub's clock's nanoseconds); the sockets are the caller's.
 *
 * @param <S> a session's socket
 */
final class UdpSessions<S> {

    /** One sender and its socket toward the target. */
    static final class Session<S> {
        private final InetSocketAddress sender;
        private final S socket;
        private long lastNs;

        private Session(InetSocketAddress sender, S socket, long nowNs) {
            this.sender = sender;
            this.socket = socket;
            this.lastNs = nowNs;
        }

        InetSocketAddress sender() {
            return sender;
        }

        S socket() {
            return socket;
        }
    }

    private final long idleNs;
    /** By sender, in the order they came. */
    private final Map<InetSocketAddress, Session<S>> bySender = new LinkedHashMap<>();

    UdpSessions(long idleNs) {
        if (idleNs <= 0) {
            throw new IllegalArgumentException("an idle time above 0, not " + idleNs);
        }
        this.idleNs = idleNs;
    }

    /** The sender's session, null when it has none; a datagram from it is passing: its idle time starts again. */
    Session<S> from(InetSocketAddress sender, long nowNs) {
        Session<S> session = bySender.get(sender);
        if (session != null) {
            session.lastNs = nowNs;
        }
        return session;
    }

    /** A new session for the sender, with its socket. */
    Session<S> open(InetSocketAddress sender, S socket, long nowNs) {
        if (bySender.containsKey(sender)) {
            throw new IllegalStateException(sender + " has a session");
        }
        Session<S> session = new Session<>(sender, socket, nowNs);
        bySender.put(sender, session);
        return session;
    }

    /** An answer came back on the session's socket: its idle time starts again. */
    void answered(Session<S> session, long nowNs) {
        session.lastNs = nowNs;
    }

    /** The sessions idle for the idle time or longer at {@code nowNs}, removed: the caller closes their sockets. */
    List<Session<S>> expire(long nowNs) {
        List<Session<S>> expired = new ArrayList<>();
        for (Iterator<Session<S>> it = bySender.values().iterator(); it.hasNext();) {
            Session<S> session = it.next();
            if (nowNs - session.lastNs >= idleNs) {
                expired.add(session);
                it.remove();
            }
        }
        return expired;
    }

    /** Nanoseconds from {@code nowNs} until the next session expires; {@link Long#MAX_VALUE} with none. */
    long nanosUntilExpiry(long nowNs) {
        long next = Long.MAX_VALUE;
        for (Session<S> session : bySender.values()) {
            next = Math.min(next, Math.max(0, session.lastNs + idleNs - nowNs));
        }
        return next;
    }

    /** Every session, removed: the caller closes their sockets (the port stops, or its pair broke). */
    Collection<Session<S>> removeAll() {
        List<Session<S>> all = new ArrayList<>(bySender.values());
        bySender.clear();
        return all;
    }

    int size() {
        return bySender.size();
    }
}
