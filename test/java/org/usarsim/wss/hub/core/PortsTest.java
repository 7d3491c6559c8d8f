package org.usarsim.wss.hub.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.RobotPair;

/** The core's ports by key and their indexes by pair and by robot: no sockets. */
class PortsTest {

    private final Ports ports = new Ports();
    private int nextNumber = 40000;

    @Test
    void indexesFollowAddAndRemove() {
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
        assertEquals(0, ports.fromCount("A"));
    }

    @Test
    void aSecondPortForOneKeyIsRefused() {
        WssPort first = add("A", "B", 5000);
        WssPort second = new WssPort(new PortKey("A", "B", 5000), nextNumber++);
        assertThrows(IllegalStateException.class, () -> ports.add(second));
        assertSame(first, ports.get(new PortKey("A", "B", 5000)));
        assertEquals(List.of(first), ports.of("B"));
    }

    private WssPort add(String from, String to, int targetPort) {
        WssPort port = new WssPort(new PortKey(from, to, targetPort), nextNumber++);
        ports.add(port);
        return port;
    }
}
