package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.net.InetAddress;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.RobotPair;

/** The hub's ports by key and their indexes by pair and by robot; ports that do not listen, on 127.0.0.1. */
class PortsTest {

    private final Ports ports = new Ports();
    private final List<WssPort> allocated = new ArrayList<>();

    @AfterEach
    void release() {
        allocated.forEach(WssPort::release);
    }

    @Test
    void indexesFollowAddAndRemove() throws IOException {
        WssPort ab = add("A", "B", 5000);
        WssPort ba = add("B", "A", 5000);
        WssPort ac = add("A", "C", 5000);
        WssPort ab2 = add("A", "B", 6000);

        assertSame(ab, ports.get(new PortKey("A", "B", 5000)));
        assertEquals(List.of(ab, ba, ab2), ports.between(RobotPair.of("B", "A")), "either way, in the order added");
        assertEquals(List.of(ab, ba, ac, ab2), ports.of("A"));
        assertEquals(List.of(ac), ports.of("C"));
        assertEquals(List.of(), ports.between(RobotPair.of("B", "C")));
        assertEquals(3, ports.fromCount("A"));
        assertEquals(1, ports.fromCount("B"));

        for (WssPort port : ports.between(RobotPair.of("A", "B"))) {
            ports.remove(port); // a copy: removing while going through it is safe
        }
        assertNull(ports.get(new PortKey("A", "B", 5000)));
        assertEquals(List.of(), ports.between(RobotPair.of("A", "B")));
        assertEquals(List.of(ac), ports.of("A"));
        assertEquals(List.of(), ports.of("B"));
        assertEquals(List.of(ac), List.copyOf(ports.all()));
        ports.remove(ab); // twice is harmless
        assertEquals(1, ports.fromCount("A"));

        ports.clear();
        assertEquals(List.of(), List.copyOf(ports.all()));
        assertEquals(List.of(), ports.of("A"));
        assertEquals(List.of(), ports.between(RobotPair.of("A", "C")));
    }

    @Test
    void aSecondPortForOneKeyIsRefused() throws IOException {
        WssPort first = add("A", "B", 5000);
        WssPort second = WssPort.allocate(null, new PortKey("A", "B", 5000), InetAddress.getLoopbackAddress(), false);
        allocated.add(second);
        assertThrows(IllegalStateException.class, () -> ports.add(second));
        assertSame(first, ports.get(new PortKey("A", "B", 5000)));
        assertEquals(List.of(first), ports.of("B"));
    }

    /** A port that holds its number without listening (no hub needed for that). */
    private WssPort add(String from, String to, int targetPort) throws IOException {
        WssPort port = WssPort.allocate(null, new PortKey(from, to, targetPort), InetAddress.getLoopbackAddress(), false);
        allocated.add(port);
        ports.add(port);
        return port;
    }
}
