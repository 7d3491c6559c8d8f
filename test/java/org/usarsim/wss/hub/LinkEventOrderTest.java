package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.model.WssEventListener;

/**
 * A link's events never come before the change that let it exist: a pair forced up while a source
 * robot keeps trying to connect, and a listener slow to take the force (a busy console) holding
 * it until the link's target has accepted: the events still read FORCED up, then the connection
 * established, then its data.
 */
class LinkEventOrderTest {

    @Test
    void aLinkThatAForceUpLetsExistIsEstablishedAndSendsAfterTheForce() throws Exception {
        try (TestHub server = new TestHub(); TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            Hub hub = server.hub;
            hub.force("R1", "R2", Force.DOWN);
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            int port = r2.dns("R1", 0);

            CountDownLatch targetAccepted = new CountDownLatch(1);
            List<String> seen = new CopyOnWriteArrayList<>();
            hub.addListener(new WssEventListener() {
                @Override
                public void pairForced(String first, String second, boolean up) {
                    if (up) {
                        try { // the slow listener: the link is made meanwhile
                            targetAccepted.await(5, TimeUnit.SECONDS);
                        } catch (InterruptedException e) {
                            Thread.currentThread().interrupt();
                        }
                    }
                }
            });
            hub.addListener(new WssEventListener() {
                @Override
                public void pairForced(String first, String second, boolean up) {
                    seen.add(up ? "forced up" : "forced down");
                }

                @Override
                public void connectionEstablished(String from, String to, int targetPort) {
                    seen.add("established");
                }

                @Override
                public void dataSent(String from, String to, int bytes) {
                    if (!seen.contains("data")) {
                        seen.add("data");
                    }
                }
            });

            Thread source = new Thread(() -> connectAndSend(port), "source");
            source.setDaemon(true);
            source.start();
            Thread accepting = new Thread(() -> {
                try (Socket target = r1Accepts.accept()) {
                    targetAccepted.countDown();
                    target.getInputStream().read(); // holds the connection until the data comes
                } catch (Exception e) {
                    // the test's end
                }
            }, "target");
            accepting.setDaemon(true);
            accepting.start();

            hub.force("R1", "R2", Force.UP);
            Wait.until("the data was sent", () -> seen.contains("data"));
            assertTrue(targetAccepted.await(5, TimeUnit.SECONDS), "the link reached its target while the force was being delivered");
            assertEquals(List.of("forced up", "established", "data"), seen);
        }
    }

    /** Tries to connect until the port listens (it is forced down at first), then sends. */
    private static void connectAndSend(int port) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (System.nanoTime() < deadline) {
            try (Socket socket = new Socket("127.0.0.1", port)) {
                OutputStream out = socket.getOutputStream();
                out.write("hello".getBytes());
                out.flush();
                socket.getInputStream().read(); // until the test ends
                return;
            } catch (Exception e) {
                Thread.onSpinWait(); // refused: not listening yet
            }
        }
    }
}
