package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.InputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.logging.Level;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/**
 * A WSS port's number stays the hub's while a departing robot's ports drain: robots leave while
 * others DNS new pairs, and no two ports ever share a number.
 */
class DrainNumberTest {

    private static final int LEAVERS = 8;
    private static final int ROUNDS = 2;
    private static final int DNSERS = 8;

    @Test
    void drainingPortsKeepTheirNumbersWhileOthersAllocate() throws Exception {
        try (LogCapture log = LogCapture.of("org.usarsim.wss.hub", Level.WARNING);
             TestHub hub = new TestHub(new NoopPropagationModel(), TestHub.config(true, 65536, 600, 1000, 30))) {
            TestRobot target = hub.robot();
            ServerSocket targetAccepts = target.initAccepting("target");
            List<TestRobot> dnsers = new ArrayList<>();
            for (int i = 0; i < DNSERS; i++) {
                TestRobot robot = hub.robot();
                robot.initAccepting("d" + i);
                dnsers.add(robot);
            }
            ExecutorService pool = Executors.newFixedThreadPool(LEAVERS + DNSERS);
            try {
                for (int round = 0; round < ROUNDS; round++) {
                    List<TestRobot> leavers = new ArrayList<>();
                    for (int i = 0; i < LEAVERS; i++) {
                        TestRobot robot = hub.robot();
                        robot.initAccepting("l" + round + "_" + i);
                        robot.dns("target", 0);
                        target.dns("l" + round + "_" + i, 0);
                        leavers.add(robot);
                    }
                    List<Future<?>> work = new ArrayList<>();
                    for (TestRobot robot : leavers) {
                        work.add(pool.submit(() -> {
                            robot.close();
                            return null;
                        }));
                    }
                    int r = round;
                    for (int i = 0; i < DNSERS; i++) {
                        TestRobot robot = dnsers.get(i);
                        work.add(pool.submit(() -> {
                            for (int j = 0; j < LEAVERS; j++) {
                                robot.dns("l" + r + "_" + j, 0); // an allocation, or NO SUCH ROBOT once gone
                            }
                            return null;
                        }));
                    }
                    for (Future<?> f : work) {
                        try {
                            f.get();
                        } catch (java.util.concurrent.ExecutionException e) {
                            if (!(e.getCause() instanceof AssertionError)) {
                                throw e;
                            }
                        }
                    }
                    Wait.until("round " + round + "'s robots are gone",
                            () -> hub.hub.snapshot().robots().size() == 1 + DNSERS);
                }
                // Every dnser's port to the target, allocated last, carries its own bytes to the target.
                for (int i = 0; i < DNSERS; i++) {
                    int number = dnsers.get(i).dns("target", 0);
                    try (Socket data = dnsers.get(i).connect(number); Socket arrived = targetAccepts.accept()) {
                        data.getOutputStream().write(("from d" + i + "\n").getBytes(StandardCharsets.UTF_8));
                        InputStream in = arrived.getInputStream();
                        assertEquals("from d" + i, new String(in.readNBytes(("from d" + i).length()), StandardCharsets.UTF_8));
                    }
                }
            } finally {
                pool.shutdownNow();
            }
            Set<Integer> numbers = new HashSet<>();
            List<HubSnapshot.PortEntry> ports = hub.hub.snapshot().ports();
            for (HubSnapshot.PortEntry port : ports) {
                if (!numbers.add(port.wssPort())) {
                    throw new AssertionError("two WSS ports share number " + port.wssPort() + ": " + ports);
                }
            }
            assertEquals(0, log.count(Level.WARNING, "could not"), log.toString());
        }
    }

    /**
     * While a robot with many listening ports leaves, probes try to bind each of its numbers (no
     * SO_REUSEADDR, so any socket of the hub's on the number makes the bind fail): none may succeed.
     */
    @Test
    void aDepartingRobotsNumbersAreNeverFree() throws Exception {
        try (LogCapture log = LogCapture.of("org.usarsim.wss.hub", Level.WARNING);
             TestHub hub = new TestHub(new NoopPropagationModel(), TestHub.config(true, 65536, 600, 1000, 30))) {
            List<TestRobot> others = new ArrayList<>();
            for (int i = 0; i < 16; i++) {
                TestRobot robot = hub.robot();
                robot.initAccepting("o" + i);
                others.add(robot);
            }
            java.util.concurrent.atomic.AtomicInteger freed = new java.util.concurrent.atomic.AtomicInteger();
            for (int round = 0; round < 5; round++) {
                TestRobot leaver = hub.robot();
                leaver.initAccepting("leaver");
                List<Integer> numbers = new ArrayList<>();
                for (int i = 0; i < others.size(); i++) {
                    numbers.add(leaver.dns("o" + i, 0));
                    numbers.add(others.get(i).dns("leaver", 0));
                }
                java.util.concurrent.atomic.AtomicBoolean done = new java.util.concurrent.atomic.AtomicBoolean();
                List<Thread> probes = new ArrayList<>();
                for (int p = 0; p < 2; p++) {
                    int first = p;
                    Thread probe = new Thread(() -> {
                        while (!done.get()) {
                            for (int k = first; k < numbers.size(); k += 2) {
                                try (java.nio.channels.SocketChannel s = java.nio.channels.SocketChannel.open()) {
                                    s.bind(new java.net.InetSocketAddress("127.0.0.1", numbers.get(k)));
                                    freed.incrementAndGet();
                                } catch (java.io.IOException e) {
                                    // in use: as it should be
                                }
                            }
                        }
                    });
                    probe.start();
                    probes.add(probe);
                }
                leaver.close();
                Wait.until("the leaver is gone", () -> hub.hub.snapshot().robots().size() == others.size());
                done.set(true);
                for (Thread probe : probes) {
                    probe.join();
                }
                hub.hub.robotLinks().kickOutRobot("leaver"); // forget its ports for the next round
            }
            assertEquals(0, freed.get(), "binds that got a number the hub still owned");
            assertEquals(0, log.count(Level.WARNING, "could not"), log.toString());
        }
    }
}
