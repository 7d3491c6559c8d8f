package org.usarsim.wss.hub;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.Map;
import java.util.Set;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.shaping.ShapingConfig;

/** A hub on 127.0.0.1 with an OS-chosen control port, for one test. */
public final class TestHub implements AutoCloseable {

    public final Hub hub;

    public TestHub() throws Exception {
        this(new NoopPropagationModel(), true, 65536);
    }

    public TestHub(PropagationModel model, boolean matchSourceAddress, int chunkSize) throws Exception {
        this(model, config(matchSourceAddress, chunkSize, 600, 1000, 30));
    }

    public TestHub(PropagationModel model, HubConfig config) throws Exception {
        this(model, config, HubClock.SYSTEM);
    }

    /** A hub on {@code clock} (a {@link ManualHubClock}: the test moves the hub's time). */
    public TestHub(PropagationModel model, HubConfig config, HubClock clock) throws Exception {
        hub = new Hub(config, model, clock);
        hub.start();
    }

    /** The test configuration: 127.0.0.1, an OS-chosen control port, 4 MiB link buffers. */
    public static HubConfig config(boolean matchSourceAddress, int chunkSize, int portMemorySeconds, int maxPortsPerRobot,
            int deadPeerSeconds) throws UnknownHostException {
        InetAddress local = InetAddress.getByName("127.0.0.1");
        return new HubConfig(local, 0, chunkSize, 4 * 1024 * 1024, matchSourceAddress, portMemorySeconds, maxPortsPerRobot,
                HubConfig.MAX_PORTS_PER_ADDRESS, deadPeerSeconds, Set.of(local), Map.of(), Map.of(), ShapingConfig.OFF, FixedSetup.NONE);
    }

    public int port() {
        return hub.controlPort();
    }

    /** A robot whose control connection comes from 127.0.0.1. */
    public TestRobot robot() throws Exception {
        return new TestRobot(port(), "127.0.0.1");
    }

    /** A robot whose control connection (and listening sockets) are on the given loopback address. */
    public TestRobot robotAt(String address) throws Exception {
        return new TestRobot(port(), address);
    }

    @Override
    public void close() {
        hub.close();
    }
}
