package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;

/**
 * Per-robot topics as a real ROS graph has them (issue 31, fault 1): the WSS subscribes to a
 * robot's {@code /NAME/odom} as it registers, and rosbridge's first message on it comes only once
 * ROS has connected the subscription to the robot's publisher (here 300 ms after the subscribe,
 * then 5 Hz). Robots registered one after another are all kept; a robot whose topic never
 * publishes is kicked once the grace has run out.
 */
@Tag("slow")
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RosbridgeRobotTopicsTest {

    private static final long SET_UP_NS = TimeUnit.MILLISECONDS.toNanos(300);

    private TinyRosbridge rosbridge;
    private ModelRig rig;
    private Thread publisher;
    private volatile boolean publishing = true;
    /** Each robot with a publisher, where it is. */
    private final Map<String, double[]> world = new ConcurrentHashMap<>();

    @AfterEach
    void stop() throws Exception {
        publishing = false;
        if (publisher != null) {
            publisher.interrupt();
            publisher.join(5_000);
        }
        if (rig != null) {
            rig.close();
        }
        if (rosbridge != null) {
            rosbridge.close();
        }
    }

    /** Publishes each robot's odometry at 5 Hz from 300 ms after the WSS subscribed to its topic. */
    private void startPublisher() {
        publisher = new Thread(() -> {
            Map<String, Long> subscribedAt = new LinkedHashMap<>();
            long start = System.nanoTime();
            while (publishing) {
                long now = System.nanoTime();
                for (String request : rosbridge.received()) {
                    world.keySet().stream().filter(robot -> request.contains("\"topic\":\"/" + robot + "/odom\""))
                            .forEach(robot -> subscribedAt.putIfAbsent(robot, now));
                }
                subscribedAt.forEach((robot, at) -> {
                    double[] place = world.get(robot);
                    if (now - at >= SET_UP_NS && place != null) {
                        rosbridge.publish(TinyRosbridge.odometry(robot, place[0], place[1], 1000 + (now - start) / 1e9));
                    }
                });
                try {
                    Thread.sleep(200); // the robots' 5 Hz, not a wait of the test
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "odometry publisher");
        publisher.setDaemon(true);
        publisher.start();
    }

    @Test
    void robotsRegisteredOneAfterAnotherAreAllKeptAndOneWhoseTopicNeverPublishesIsKickedAfterTheGrace() throws Exception {
        List<String> robots = List.of("WA", "WB", "WC", "WD");
        for (int i = 0; i < robots.size(); i++) {
            world.put(robots.get(i), new double[] {i * 5.0, 0});
        }
        rosbridge = new TinyRosbridge();
        startPublisher();
        Map<String, String> settings = new LinkedHashMap<>();
        settings.put("positions", "rosbridge");
        settings.put("rosbridge.url", rosbridge.url());
        settings.put("rosbridge.topic", "/{robot}/odom");
        settings.put("rosbridge.grace", "5000");
        settings.put("positions.interval", "100");
        rig = ModelRig.polling(1, new DistanceOnlyPropagationModel(), settings);
        for (String robot : robots) {
            rig.robot(robot);
        }
        Wait.until("every robot placed", () -> robots.stream().allMatch(robot -> rig.model.positionOf(robot).isPresent()));
        long placed = System.nanoTime();
        rig.robot("Ghost"); // registered, its topic never publishes
        Wait.until("the robot without messages kicked", TimeUnit.SECONDS.toNanos(15),
                () -> rig.server.hub.getListOfRegisteredRobots().equals(robots));
        assertTrue(System.nanoTime() - placed >= TimeUnit.MILLISECONDS.toNanos(5_000), "not before its grace of 5 s");
        assertEquals(1, rig.logLines(Level.INFO, "kicking Ghost"));
        assertEquals(1, rig.logLines(Level.INFO, "kicking"), "nobody else kicked");
    }
}
