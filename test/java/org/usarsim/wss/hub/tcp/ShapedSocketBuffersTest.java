package org.usarsim.wss.hub.tcp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import org.junit.jupiter.api.Test;

/** A shaped link's kernel buffers (issue 27, item 3; docs/shaping.md, "The queue"): 20 ms at the rate, a floor by where the robot is. */
class ShapedSocketBuffersTest {

    @Test
    void aSlowLinkAcrossANetworkGetsAFewSegmentsNotHalfASecond() {
        assertEquals(8 * 1024, LiveShaping.socketBuffer(1_000_000, false));
        assertEquals(8 * 1024, LiveShaping.socketBuffer(1, false));
        assertEquals(15_000, LiveShaping.socketBuffer(6_000_000, false)); // 20 ms at 6 Mbit/s
    }

    @Test
    void aRobotOnThisMachineKeepsTheLoopbacksFloor() {
        assertEquals(64 * 1024, LiveShaping.socketBuffer(1_000_000, true));
        assertEquals(64 * 1024, LiveShaping.socketBuffer(6_000_000, true));
    }

    @Test
    void aFastLinkGetsTwentyMillisecondsAtItsRateWhereverTheRobotIs() {
        assertEquals(135_000, LiveShaping.socketBuffer(54_000_000, false));
        assertEquals(135_000, LiveShaping.socketBuffer(54_000_000, true));
        assertEquals(1 << 22, LiveShaping.socketBuffer(100_000_000_000L, false)); // at most 4 MiB
    }

    @Test
    void aConnectionFromLoopbackIsFromThisMachine() throws Exception {
        try (ServerSocketChannel server = ServerSocketChannel.open()) {
            server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            try (SocketChannel client = SocketChannel.open(server.getLocalAddress()); SocketChannel accepted = server.accept()) {
                assertTrue(LiveShaping.onThisMachine(accepted));
                assertTrue(LiveShaping.onThisMachine(client));
            }
        }
    }
}
