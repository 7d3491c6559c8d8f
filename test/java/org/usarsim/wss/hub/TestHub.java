package org.usarsim.wss.hub;

import java.net.InetAddress;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/** A hub on 127.0.0.1 with an OS-chosen control port, for one test. */
public final class TestHub implements AutoCloseable {

    public final Hub hub;

    public TestHub() throws Exception {
        this(new NoopPropagationModel(), true, 65536);
    }

    public TestHub(PropagationModel model, boolean matchSourceAddress, int chunkSize) throws Exception {
        hub = new Hub(new HubConfig(InetAddress.getByName("127.0.0.1"), 0, chunkSize, 4 * 1024 * 1024, matchSourceAddress), model);
        hub.start();
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
