package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.junit.jupiter.api.Test;

/** Many robots racing to INIT one name: exactly one wins. */
class InitRaceTest {

    private static final int RACERS = 50;

    @Test
    void exactlyOneOfFiftyRobotsRacingForANameWins() throws Exception {
        ExecutorService pool = Executors.newFixedThreadPool(RACERS);
        List<TestRobot> robots = new ArrayList<>();
        try (TestHub server = new TestHub()) {
            for (int i = 0; i < RACERS; i++) {
                robots.add(server.robot());
            }
            CountDownLatch go = new CountDownLatch(1);
            List<Future<String>> replies = new ArrayList<>();
            for (TestRobot robot : robots) {
                replies.add(pool.submit(() -> {
                    go.await();
                    return robot.ask("INIT {Robot Same} {Port 5000}");
                }));
            }
            go.countDown();
            Map<String, Integer> counts = new TreeMap<>();
            TestRobot winner = null;
            for (int i = 0; i < RACERS; i++) {
                String reply = replies.get(i).get();
                counts.merge(reply, 1, Integer::sum);
                if (reply.equals("INITREPLY {Status OK}")) {
                    winner = robots.get(i);
                }
            }
            assertEquals(Map.of("INITREPLY {Status OK}", 1, "ERROR {Reason Robot.Alread.Exists}", RACERS - 1), counts);
            assertEquals(List.of("Same"), server.hub.getListOfRegisteredRobots());

            winner.control.close();
            Wait.until("the winner is deregistered", () -> server.hub.getListOfRegisteredRobots().isEmpty());
            TestRobot loser = robots.get(robots.indexOf(winner) == 0 ? 1 : 0);
            assertEquals("INITREPLY {Status OK}", loser.ask("INIT {Robot Same}"), "a loser may take the name once it is free");
        } finally {
            for (TestRobot robot : robots) {
                robot.close();
            }
            pool.shutdownNow();
        }
    }
}
