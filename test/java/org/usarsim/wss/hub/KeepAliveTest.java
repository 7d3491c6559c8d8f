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
    void theTimingFitsTheSetting() {
        for (int seconds : new int[] {2, 3, 5, 10, 30, 31, 600, 86400}) {
            KeepAlive keepAlive = KeepAlive.within(seconds);
            assertTrue(keepAlive.idle >= 1 && keepAlive.interval >= 1 && keepAlive.count >= 1, keepAlive.toString());
            assertTrue(keepAlive.detectionSeconds() <= seconds, seconds + " s: " + keepAlive);
            assertTrue(keepAlive.idle <= 32767 && keepAlive.interval <= 32767 && keepAlive.count <= 127, keepAlive.toString());
        }
        KeepAlive thirty = KeepAlive.within(30);
        assertEquals(List.of(10, 5, 4), List.of(thirty.idle, thirty.interval, thirty.count));
        assertEquals(0, KeepAlive.within(0).detectionSeconds(), "0: the OS's timing");
        assertEquals(2, KeepAlive.within(1).detectionSeconds(), "1: the least keepalive can do, one idle second and one probe");
    }

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
        try (LogCapture log = LogCapture.of(ControlSession.class.getName(), Level.INFO);
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
