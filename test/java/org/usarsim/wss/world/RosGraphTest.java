package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.world.RosGraph.Publication;

/** The world server's ROS graph: who publishes what, when, in the world's time. */
class RosGraphTest {

    private static final long MS = 1_000_000L;
    private static final List<String> ROBOTS = List.of("A", "B", "C", "D");

    private final RosGraph graph = new RosGraph(ROBOTS, 20, 300 * MS);

    private static String names(List<Publication> publications) {
        return String.join(" ", publications.stream().map(p -> p.publisher().topic() + ":" + p.publisher().robot() + "@"
                + p.nanos() / MS + "#" + p.seq()).toList());
    }

    @Test
    void theTopicsTheirTypesAndWhoIsLatched() {
        assertEquals(List.of("/gazebo/model_states", "/tf", "/tf_static", "/map", "/A/odom", "/B/odom", "/C/odom", "/D/odom"),
                graph.topics());
        assertEquals("tf2_msgs/TFMessage", graph.type("/tf_static"));
        assertEquals("nav_msgs/Odometry", graph.type("/C/odom"));
        assertNull(graph.type("/E/odom"));
        assertTrue(graph.latched("/tf_static").latched());
        assertNull(graph.latched("/tf"));
        assertEquals(300 * MS, graph.startDelay("/B/odom"), "a per-robot topic waits for its connection");
        assertEquals(0, graph.startDelay("/tf"));
        assertEquals("tf2_msgs/TFMessage", new RosGraph(List.of(), 20, 0).type("/tf"), "no robot: /tf is still a topic");
    }

    @Test
    void tfHasOnePublisherPerRobotStaggeredAcrossThePeriod() {
        assertEquals("/tf:0@0#0", names(graph.next("/tf", -1)));
        assertEquals("/tf:1@12#0", names(graph.next("/tf", 0)), "a quarter of the 50 ms period later");
        assertEquals("/tf:2@25#0", names(graph.next("/tf", 12_500_000L)));
        assertEquals("/tf:3@37#0", names(graph.next("/tf", 25 * MS)));
        assertEquals("/tf:0@50#1", names(graph.next("/tf", 37_500_000L)));
        assertEquals("/gazebo/model_states:-1@1000#20", names(graph.next("/gazebo/model_states", 999 * MS)));
        assertEquals("/C/odom:2@1025#20", names(graph.next("/C/odom", 1000 * MS)), "its robot's phase");
        assertEquals("", names(graph.next("/map", 0)), "latched: published once, at 0, not periodically");
    }

    @Test
    void theFirstPublishAtOrAfterATimeForTheBenchmark() {
        assertEquals(12_500_000L, graph.firstPublishAtOrAfter("/tf", "B", 12_500_000L), "at: the instant itself");
        assertEquals(62_500_000L, graph.firstPublishAtOrAfter("/tf", "B", 12_500_001L));
        assertEquals(0, graph.firstPublishAtOrAfter("/gazebo/model_states", null, 0));
        assertEquals(1050 * MS, graph.firstPublishAtOrAfter("/gazebo/model_states", "anyone", 1001 * MS));
        assertEquals(37_500_000L, graph.firstPublishAtOrAfter("/D/odom", null, 0));
        assertEquals(0, graph.firstPublishAtOrAfter("/tf_static", null, 0));
        assertEquals(Long.MAX_VALUE, graph.firstPublishAtOrAfter("/map", null, 1));
        assertThrows(IllegalArgumentException.class, () -> graph.firstPublishAtOrAfter("/tf", "E", 0));
        assertThrows(IllegalArgumentException.class, () -> graph.firstPublishAtOrAfter("/nothing", null, 0));
        assertEquals(0.0625, RosbridgeServer.firstPublishAtOrAfter("/tf", "B", ROBOTS, 20, 0.0125001), 1e-12);
        assertEquals(Double.POSITIVE_INFINITY, RosbridgeServer.firstPublishAtOrAfter("/tf_static", null, ROBOTS, 20, 3));
        assertEquals(0.4, RosbridgeServer.firstPublishAtOrAfter("/gazebo/model_states", null, ROBOTS, 5, 0.3), 1e-12);
        assertEquals(0.02, RosbridgeServer.firstPublishAtOrAfter("/gazebo/model_states", null, ROBOTS, 50, 0.011), 1e-12);
    }

    @Test
    void aRateAbove0AndAtMost1000() {
        assertEquals(200 * MS, RosGraph.periodNanos(5));
        assertEquals(20 * MS, RosGraph.periodNanos(50));
        assertThrows(IllegalArgumentException.class, () -> RosGraph.periodNanos(0));
        assertThrows(IllegalArgumentException.class, () -> RosGraph.periodNanos(1001));
        assertThrows(IllegalArgumentException.class, () -> RosGraph.periodNanos(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> new RosGraph(ROBOTS, 20, -1));
    }
}
