package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.core.DeclaredRobot;
import org.usarsim.wss.hub.core.FixedPort;
import org.usarsim.wss.hub.core.PortKey;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.shaping.JitterConfig;
import org.usarsim.wss.shaping.JitterDistribution;
import org.usarsim.wss.shaping.LossTable;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * Issue 35: a real fixed UDP port with a jitter of 15 ms on a delay of 20 ms, 60 numbered
 * datagrams a millisecond apart: in order without {@code wss.shaping.reorder} whatever the draws,
 * overtaking each other with it.
 */
@Tag("slow")
class JitteredUdpPortTest {

    private static final InetAddress LOCAL = InetAddress.getLoopbackAddress();
    private static final int COUNT = 60;

    private static List<Integer> arrivals(boolean reorder) throws Exception {
        try (DatagramSocket base = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
            int number = Sockets.freeUdp();
            HubConfig config = TestHub.config(true, 65536, 600, 1000, 30)
                    .withShaping(new ShapingConfig(true, RateTable.DEFAULT, 20, true, ShapingConfig.DEFAULT_QUEUE_MS, LossTable.parse(""),
                            new JitterConfig(15, JitterDistribution.UNIFORM, reorder, 3)), Map.of())
                    .withFixed(new FixedSetup(List.of(new DeclaredRobot("Base", LOCAL), new DeclaredRobot("Scout", LOCAL)),
                            List.of(new FixedPort(FixedPort.Transport.UDP, new PortKey("Scout", "Base", base.getLocalPort()), number)), 60));
            try (TestHub test = new TestHub(new NoopPropagationModel(), config);
                    DatagramSocket scout = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
                byte[] data = new byte[4];
                long start = System.nanoTime();
                for (int i = 0; i < COUNT; i++) {
                    ByteBuffer.wrap(data).putInt(0, i);
                    scout.send(new DatagramPacket(data, 4, LOCAL, number));
                    long next = start + (i + 1) * 1_000_000L;
                    while (System.nanoTime() - next < 0) {
                        java.util.concurrent.locks.LockSupport.parkNanos(next - System.nanoTime()); // pacing, not a wait for a result
                    }
                }
                List<Integer> order = new ArrayList<>();
                base.setSoTimeout(5000);
                DatagramPacket packet = new DatagramPacket(new byte[16], 16);
                while (order.size() < COUNT) {
                    base.receive(packet);
                    order.add(ByteBuffer.wrap(packet.getData(), 0, 4).getInt());
                }
                return order;
            }
        }
    }

    @Test
    void withoutReorderDatagramsArriveInOrderWhateverTheirJitter() throws Exception {
        List<Integer> order = arrivals(false);
        for (int i = 0; i < COUNT; i++) {
            assertEquals(i, order.get(i), order.toString());
        }
    }

    @Test
    void withReorderLaterDatagramsOvertake() throws Exception {
        List<Integer> order = arrivals(true);
        int overtaken = 0;
        for (int i = 1; i < COUNT; i++) {
            overtaken += order.get(i) < order.get(i - 1) ? 1 : 0;
        }
        assertTrue(overtaken > 5, "+- 15 ms on datagrams 1 ms apart: " + order);
        assertEquals(COUNT, order.stream().distinct().count(), "each once");
    }
}
