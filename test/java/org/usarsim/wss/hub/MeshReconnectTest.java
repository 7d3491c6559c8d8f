package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * A whole team in full mesh loses its control connections at once and every robot reconnects
 * at once (a robot team's client does): every INIT again is accepted, every port listens again.
 */
@Tag("slow")
class MeshReconnectTest {

    private static final int ROBOTS = 40;

    @Test
    void aFullMeshReconnectingAtOnceIsAllAccepted() throws Exception {
        try (TestHub hub = new TestHub()) {
            List<TestRobot> robots = new ArrayList<>();
            List<Integer> accepting = new ArrayList<>();
            for (int i = 0; i < ROBOTS; i++) {
                TestRobot robot = hub.robot();
                accepting.add(robot.initAccepting("R" + i).getLocalPort());
                robots.add(robot);
            }
            for (int i = 0; i < ROBOTS; i++) {
                for (int j = 0; j < ROBOTS; j++) {
                    if (i != j) {
                        robots.get(i).dns("R" + j, 0);
                    }
                }
            }
            int ports = ROBOTS * (ROBOTS - 1);
            assertEquals(ports, hub.hub.snapshot().ports().stream().filter(HubSnapshot.PortEntry::listening).count());
            ExecutorService pool = Executors.newFixedThreadPool(ROBOTS);
            List<TestRobot> again = new ArrayList<>();
            try {
                for (int i = 0; i < ROBOTS; i++) {
                    again.add(hub.robot());
                }
                List<Future<String>> replies = new ArrayList<>();
                for (int i = 0; i < ROBOTS; i++) {
                    TestRobot old = robots.get(i);
                    TestRobot fresh = again.get(i);
                    String init = "INIT {Robot R" + i + "} {Port " + accepting.get(i) + "}";
                    replies.add(pool.submit(() -> {
                        old.control.close();
                        return fresh.ask(init);
                    }));
                }
                for (int i = 0; i < ROBOTS; i++) {
                    assertEquals("INITREPLY {Status OK}", replies.get(i).get(30, TimeUnit.SECONDS), "R" + i + "'s INIT again");
                }
                Wait.until("every port listens again", () -> hub.hub.snapshot().ports().stream()
                        .filter(HubSnapshot.PortEntry::listening).count() == ports);
                List<Future<String>> strengths = new ArrayList<>();
                for (int i = 0; i < ROBOTS; i++) {
                    TestRobot robot = again.get(i);
                    String ask = "GETSS {Robot R" + ((i + 1) % ROBOTS) + "}";
                    strengths.add(pool.submit(() -> robot.ask(ask)));
                }
                for (Future<String> reply : strengths) {
                    assertTrue(reply.get(30, TimeUnit.SECONDS).startsWith("SS {Robot R"));
                }
            } finally {
                pool.shutdownNow();
                for (TestRobot robot : robots) {
                    robot.close();
                }
                for (TestRobot robot : again) {
                    robot.close();
                }
            }
        }
    }
}
