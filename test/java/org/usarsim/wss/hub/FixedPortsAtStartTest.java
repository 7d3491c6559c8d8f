package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.core.DeclaredRobot;
import org.usarsim.wss.hub.core.FixedPort;
import org.usarsim.wss.hub.core.PortKey;

/**
 * A robot's program started by the same script as the server connects to its fixed port as soon
 * as the control port accepts (issue 32): by then every fixed port listens, TCP and UDP. Real
 * sockets on 127.0.0.1, the hub in this process; the model's start (the slow part of a start: a
 * simulator's connection) lasts until the program has tried the control port twice meanwhile.
 */
@Tag("slow")
class FixedPortsAtStartTest {

    private static final InetAddress LOCAL = InetAddress.getLoopbackAddress();

    /** The program: tries the control port until it accepts, then at once the fixed TCP port, and sends to the fixed UDP port. */
    private static final class Program extends Thread {
        final AtomicInteger tries = new AtomicInteger();
        private final int control;
        private final int tcp;
        private final int udp;
        private final DatagramSocket sender;
        volatile boolean done;
        /** What went wrong once the control port accepted; null: nothing. */
        volatile String failure;

        Program(int control, int tcp, int udp, DatagramSocket sender) {
            super("a robot's program");
            setDaemon(true);
            this.control = control;
            this.tcp = tcp;
            this.udp = udp;
            this.sender = sender;
        }

        @Override
        public void run() {
            try {
                Wait.until("the control port accepts", () -> {
                    tries.incrementAndGet();
                    return connects(control);
                });
                if (!connects(tcp)) {
                    failure = "the fixed TCP port refused a connection once the control port accepted";
                }
                byte[] hello = "hello".getBytes(StandardCharsets.US_ASCII);
                sender.send(new DatagramPacket(hello, hello.length, LOCAL, udp));
            } catch (IOException | AssertionError e) {
                failure = e.toString();
            } finally {
                done = true;
            }
        }

        private static boolean connects(int port) {
            try (Socket socket = new Socket(LOCAL, port)) {
                return true;
            } catch (IOException refused) {
                return false;
            }
        }
    }

    /** The control port is bound last, yet one in use is found before the model starts (a simulator's connection may take a while). */
    @Test
    void aControlPortInUseIsFoundBeforeTheModelStarts() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, LOCAL)) {
            ScriptedModel model = new ScriptedModel();
            AtomicInteger starts = new AtomicInteger();
            model.whileStarting(starts::incrementAndGet);
            Hub hub = new Hub(TestHub.config(true, 65536, 600, 1000, 30).withControlPort(taken.getLocalPort()), model);
            try {
                assertThrows(IOException.class, hub::start);
                assertEquals(0, starts.get(), "the model was not started");
            } finally {
                hub.close();
            }
        }
    }

    @Test
    void everyFixedPortListensOnceTheControlPortAccepts() throws Exception {
        try (ServerSocket base = new ServerSocket(0, 50, LOCAL);
                DatagramSocket baseUdp = new DatagramSocket(new InetSocketAddress(LOCAL, 0));
                DatagramSocket scoutUdp = new DatagramSocket(new InetSocketAddress(LOCAL, 0))) {
            int control = Sockets.freeTcp();
            int tcp = Sockets.freeTcp();
            int udp = Sockets.freeUdp();
            HubConfig config = TestHub.config(true, 65536, 600, 1000, 30).withControlPort(control).withFixed(new FixedSetup(
                    List.of(new DeclaredRobot("Base", LOCAL), new DeclaredRobot("Scout", LOCAL)),
                    List.of(new FixedPort(FixedPort.Transport.TCP, new PortKey("Scout", "Base", base.getLocalPort()), tcp),
                            new FixedPort(FixedPort.Transport.UDP, new PortKey("Scout", "Base", baseUdp.getLocalPort()), udp)), 60));
            Program program = new Program(control, tcp, udp, scoutUdp);
            ScriptedModel model = new ScriptedModel();
            model.whileStarting(() -> {
                int before = program.tries.get();
                Wait.until("the program tried the control port twice while the model starts",
                        () -> program.tries.get() >= before + 2 || program.done);
            });
            program.start();
            Hub hub = new Hub(config, model);
            try {
                hub.start();
                Wait.until("the program connected", () -> program.done);
                assertNull(program.failure);
                baseUdp.setSoTimeout(5000);
                DatagramPacket got = new DatagramPacket(new byte[100], 100);
                baseUdp.receive(got);
                assertEquals("hello", new String(got.getData(), 0, got.getLength(), StandardCharsets.US_ASCII),
                        "the datagram sent the moment the control port accepted");
            } finally {
                hub.close();
            }
        }
    }
}
