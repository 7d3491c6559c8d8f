package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertThrows;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/** A start that fails (the control port in use) leaves no thread behind. */
class FailedStartTest {

    private static final int STARTS = 20;

    private static long portMemoryThreads() {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.isAlive() && t.getName().equals("wss-port-memory")).count();
    }

    @Test
    void failedStartsLeaveNoPortMemoryThread() throws Exception {
        try (ServerSocket taken = new ServerSocket()) {
            taken.bind(new InetSocketAddress(InetAddress.getByName("127.0.0.1"), 0));
            HubConfig config = TestHub.config(true, 65536, 600, 1000, 30).withControlPort(taken.getLocalPort());
            long before = portMemoryThreads();
            for (int i = 0; i < STARTS; i++) {
                Hub hub = new Hub(config, new NoopPropagationModel());
                assertThrows(java.io.IOException.class, hub::start);
                Server server = Server.create(config, ModelProvider.of(NoopPropagationModel::new), new ModelSettings(Map.of()), null);
                assertThrows(Server.StartFailure.class, server::start);
            }
            Wait.until("no wss-port-memory thread is left of " + 2 * STARTS + " failed starts (" + before
                    + " before, " + portMemoryThreads() + " now)", () -> portMemoryThreads() <= before);
        }
    }
}
