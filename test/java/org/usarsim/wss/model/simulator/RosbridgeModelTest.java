package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.hub.Sockets.assertClosedByPeer;

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
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.protocol.Replies;

/**
 * The DistanceOnly model with positions from rosbridge, for real: the JDK's WebSocket client in
 * {@link RosbridgeSource} against a rosbridge on a socket of its own ({@link TinyRosbridge}),
 * {@code /gazebo/model_states} published at 20 Hz, robots registered with a hub.
 */
@Tag("slow")
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RosbridgeModelTest {

    private static final PathLoss N3 = new PathLoss(-49.67, 3, 2, -93); // a range of 55.6 m

    private TinyRosbridge rosbridge;
    private ModelRig rig;
    private Thread publisher;
    private volatile boolean publishing = true;
    /** The models and where they are: what the publisher sends, 20 times a second. */
    private final Map<String, double[]> world = new ConcurrentHashMap<>();
    private volatile int fragments = 1;
    private final LogCapture sourceLog = LogCapture.of(RosbridgeSource.class.getName(), Level.FINE);

    @AfterEach
    void stop() throws Exception {
        sourceLog.close();
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

    private void start(Map<String, String> settings) throws Exception {
        rosbridge = new TinyRosbridge();
        startPublisher();
        Map<String, String> all = new LinkedHashMap<>();
        all.put("positions", "rosbridge");
        all.put("rosbridge.url", rosbridge.url());
        all.put("distance.n", "3");
        all.putAll(settings);
        rig = ModelRig.polling(1, new DistanceOnlyPropagationModel(), all);
    }

    private void startPublisher() {
        publishing = true;
        publisher = new Thread(() -> {
            while (publishing) {
                rosbridge.publish(TinyRosbridge.modelStates(new java.util.TreeMap<>(world)), fragments);
                try {
                    Thread.sleep(50); // the simulator's 20 Hz, not a wait of the test
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "publisher");
        publisher.setDaemon(true);
        publisher.start();
    }

    private void place(String name, double x, double y) {
        world.put(name, new double[] {x, y});
    }

    @Test
    void robotsGetTheirStrengthsAndBreaksFromTheMotionAndTheSubscriptionTakesEachMessageAsItComes() throws Exception {
        place("A", 0, 0);
        place("B", 10, 0);
        place("ground_plane", 0, 0);
        start(Map.of());
        TestRobot a = rig.robot("A");
        rig.robot("B");
        String near = Replies.signal("B", N3.strength(10));
        Wait.until("GETSS from the published positions", () -> ask(a, "GETSS {Robot B}").equals(near));
        assertEquals(1, sourceLog.count(Level.INFO, "positions from " + rosbridge.url() + " /gazebo/model_states: 3 robots"),
                sourceLog.toString());
        String subscribe = rosbridge.received().get(0);
        assertTrue(subscribe.contains("\"op\":\"subscribe\"") && subscribe.contains("\"topic\":\"/gazebo/model_states\"")
                && subscribe.contains("\"type\":\"gazebo_msgs/ModelStates\"") && subscribe.contains("\"throttle_rate\":0")
                && subscribe.contains("\"queue_length\":0"), subscribe);

        place("B", 100, 0);
        Wait.until("the pair broken", () -> !rig.events("OUT_OF_RANGE").isEmpty());
        assertEquals(List.of("A", "B"), rig.events("OUT_OF_RANGE").get(0).args().subList(0, 2));
        place("B", 20, 0);
        Wait.until("the pair resumed", () -> !rig.events("IN_RANGE").isEmpty());
        String far = Replies.signal("B", N3.strength(20));
        Wait.until("GETSS follows", () -> ask(a, "GETSS {Robot B}").equals(far));
    }

    @Test
    void aSimulatorPublishingFasterThan50ASecondIsAskedForAgainThrottledTo20ms() throws Exception {
        place("A", 0, 0);
        place("B", 10, 0);
        start(Map.of());
        rig.robot("A");
        Thread fast = new Thread(() -> {
            for (int i = 0; i < 400 && publishing; i++) {
                rosbridge.publish(TinyRosbridge.modelStates(new java.util.TreeMap<>(world)), 1);
                try {
                    Thread.sleep(2); // a simulator at its physics rate (Gazebo classic's 1 kHz), not a wait of the test
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "fast publisher");
        fast.setDaemon(true);
        fast.start();
        Wait.until("asked for again", () -> rosbridge.received().size() >= 2);
        String again = rosbridge.received().get(1);
        assertTrue(again.contains("\"id\":\"wss:/gazebo/model_states\"") && again.contains("\"throttle_rate\":20")
                && again.contains("\"queue_length\":1"), again);
        Wait.until("said", () -> sourceLog.count(Level.INFO, "sends more than 50 messages a second on /gazebo/model_states") > 0);
        fast.join(10_000);
        assertEquals(2, rosbridge.received().size(), "asked for again once: " + rosbridge.received());
        assertEquals(1, sourceLog.count(Level.INFO, "sends more than 50 messages a second on /gazebo/model_states"), sourceLog.toString());
    }

    @Test
    void aRobotMissingFromModelStatesIsKicked() throws Exception {
        place("A", 0, 0);
        place("B", 10, 0);
        start(Map.of());
        rig.robot("A");
        TestRobot b = rig.robot("B");
        Wait.until("both listed", () -> rig.model.positionOf("B").isPresent());
        world.remove("B");
        assertClosedByPeer(b.control, "B, gone from /gazebo/model_states");
        Wait.until("B is deregistered", () -> rig.server.hub.getListOfRegisteredRobots().equals(List.of("A")));
        assertEquals(1, rig.logLines(Level.INFO, "kicking B"));
    }

    @Test
    void aKilledWebSocketIsSilenceSaidOnceTheStateIsKeptAndItReconnects() throws Exception {
        place("A", 0, 0);
        place("B", 10, 0);
        start(Map.of());
        TestRobot a = rig.robot("A");
        rig.robot("B");
        String near = Replies.signal("B", N3.strength(10));
        Wait.until("GETSS from the published positions", () -> ask(a, "GETSS {Robot B}").equals(near));
        publishing = false;
        publisher.interrupt();
        publisher.join(5_000);
        rosbridge.dropClients();
        Wait.until("the loss said", () -> rig.logLines(Level.WARNING, "lost the simulator at " + rosbridge.url()) == 1);
        Wait.until("a new WebSocket", () -> rosbridge.connections() >= 2);
        assertEquals(near, ask(a, "GETSS {Robot B}"), "the last state kept");
        assertEquals(List.of("A", "B"), rig.server.hub.getListOfRegisteredRobots(), "nobody kicked");
        assertEquals(1, rig.logLines(Level.WARNING, "lost the simulator at"), "said once");

        place("B", 20, 0);
        startPublisher();
        Wait.until("back", () -> rig.logLines(Level.INFO, "answers again after") == 1);
        String far = Replies.signal("B", N3.strength(20));
        Wait.until("GETSS follows again", () -> ask(a, "GETSS {Robot B}").equals(far));
    }

    @Test
    void messagesInFragmentsAreWholeAgain() throws Exception {
        fragments = 7;
        place("A", 0, 0);
        place("B", 30, 0);
        start(Map.of());
        TestRobot a = rig.robot("A");
        rig.robot("B");
        String expected = Replies.signal("B", N3.strength(30));
        Wait.until("GETSS from fragmented messages", () -> ask(a, "GETSS {Robot B}").equals(expected));
    }

    private static String ask(TestRobot robot, String command) {
        try {
            return robot.ask(command);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
