package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.ServerSocket;
import java.net.Socket;
import java.net.StandardSocketOptions;
import java.nio.channels.SocketChannel;
import java.util.List;
import java.util.logging.Level;
import jdk.net.ExtendedSocketOptions;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/** wss.deadPeerSeconds: TCP keepalive, read back from the sockets the hub accepted and opened. */
class KeepAliveTest {

    @Test
    void controlConnectionsAndBothLegsOfALinkFindADeadPeerWithinTheSetting() throws Exception {
        try (TestHub server = new TestHub(new NoopPropagationModel(), TestHub.config(true, 65536, 600, 1000, 12));
                TestRobot r1 = server.robot();
                TestRobot r2 = server.robot()) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            try (Socket source = r2.connect(r2.dns("R1", 0)); Socket target = r1Accepts.accept()) {
                Sockets.send(source, "x");
                assertEquals("x", Sockets.readExactly(target.getInputStream(), 1), "the link forwards");
                List<SocketChannel> sockets = server.hub.openSockets();
                assertEquals(4, sockets.size(), "two control connections and the link's two legs");
                for (SocketChannel socket : sockets) {
                    String what = socket.toString();
                    assertTrue(socket.getOption(StandardSocketOptions.SO_KEEPALIVE), what);
                    assertEquals(4, socket.getOption(ExtendedSocketOptions.TCP_KEEPIDLE), what);
                    assertEquals(2, socket.getOption(ExtendedSocketOptions.TCP_KEEPINTERVAL), what);
                    assertEquals(4, socket.getOption(ExtendedSocketOptions.TCP_KEEPCOUNT), what);
                }
            }
        }
    }

    @Test
    void aLostControlConnectionIsLoggedAndTheRobotDeregistered() throws Exception {
        try (LogCapture log = LogCapture.of("org.usarsim.wss.hub.tcp.ControlSession", Level.INFO);
                TestHub server = new TestHub();
                TestRobot r1 = server.robot()) {
            r1.init("R1", 5000);
            r1.control.setSoLinger(true, 0); // a reset, as a connection that failed (keepalive's "timed out" ends it the same way)
            r1.control.close();
            Wait.until("R1 is deregistered", () -> server.hub.getListOfRegisteredRobots().isEmpty());
            Wait.until("the loss is logged", () -> log.count(Level.INFO, "lost the control connection of R1 from 127.0.0.1:") == 1);
            assertTrue(log.messages(Level.INFO).stream().anyMatch(m -> m.endsWith("; deregistering it")), log.toString());
        }
    }
}
