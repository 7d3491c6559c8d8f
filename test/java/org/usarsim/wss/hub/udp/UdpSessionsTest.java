package org.usarsim.wss.hub.udp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.net.InetSocketAddress;
import java.util.List;
import org.junit.jupiter.api.Test;

/** A fixed UDP port's sessions on a moved clock. */
class UdpSessionsTest {

    private static final long SECOND = 1_000_000_000L;
    private final InetSocketAddress alice = new InetSocketAddress("127.0.0.1", 5000);
    private final InetSocketAddress bob = new InetSocketAddress("127.0.0.1", 5001);

    @Test
    void eachSenderHasItsOwnSessionFoundAgainByItsAddressAndPort() {
        UdpSessions<String> sessions = new UdpSessions<>(60 * SECOND);
        assertNull(sessions.from(alice, 0));
        UdpSessions.Session<String> a = sessions.open(alice, "socket-a", 0);
        UdpSessions.Session<String> b = sessions.open(bob, "socket-b", 0);
        assertSame(a, sessions.from(alice, SECOND));
        assertSame(b, sessions.from(new InetSocketAddress("127.0.0.1", 5001), SECOND));
        assertEquals("socket-a", a.socket());
        assertEquals(alice, a.sender());
        assertEquals(2, sessions.size());
        assertThrows(IllegalStateException.class, () -> sessions.open(alice, "again", 0));
    }

    @Test
    void aSessionExpiresAfterTheIdleTimeWithoutADatagramEitherWay() {
        long start = Long.MAX_VALUE - 30 * SECOND; // System.nanoTime() may be anywhere, and wrap
        UdpSessions<String> sessions = new UdpSessions<>(60 * SECOND);
        UdpSessions.Session<String> a = sessions.open(alice, "a", start);
        UdpSessions.Session<String> b = sessions.open(bob, "b", start);
        assertEquals(60 * SECOND, sessions.nanosUntilExpiry(start));
        sessions.from(alice, start + 40 * SECOND); // alice sends
        sessions.answered(b, start + 50 * SECOND); // bob's target answers
        assertEquals(List.of(), sessions.expire(start + 60 * SECOND - 1));
        assertEquals(List.of(), sessions.expire(start + 99 * SECOND));
        assertEquals(SECOND, sessions.nanosUntilExpiry(start + 99 * SECOND));
        assertEquals(List.of(a), sessions.expire(start + 100 * SECOND));
        assertNull(sessions.from(alice, start + 100 * SECOND));
        assertEquals(List.of(b), sessions.expire(start + 110 * SECOND));
        assertEquals(Long.MAX_VALUE, sessions.nanosUntilExpiry(start + 110 * SECOND));
    }

    @Test
    void removeAllGivesEverySessionToClose() {
        UdpSessions<String> sessions = new UdpSessions<>(SECOND);
        sessions.open(alice, "a", 0);
        sessions.open(bob, "b", 0);
        assertEquals(List.of("a", "b"), sessions.removeAll().stream().map(UdpSessions.Session::socket).toList());
        assertEquals(0, sessions.size());
    }
}
