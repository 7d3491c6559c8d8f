package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.ros.MessageType;

/** Which topics a rosbridge source asks for, with which options (issue 31: faults 2 and 3). */
class TopicRequestsTest {

    private static final long S = TimeUnit.SECONDS.toNanos(1);

    @Test
    void tfIsAskedForUnthrottledWithoutAQueueAndTfStaticBesideIt() {
        assertEquals(List.of(
                "{\"op\":\"subscribe\",\"id\":\"wss:/tf\",\"topic\":\"/tf\",\"type\":\"tf2_msgs/TFMessage\",\"throttle_rate\":0,\"queue_length\":0}",
                "{\"op\":\"subscribe\",\"id\":\"wss:/tf_static\",\"topic\":\"/tf_static\",\"type\":\"tf2_msgs/TFMessage\","
                        + "\"throttle_rate\":0,\"queue_length\":0}"),
                TopicRequests.poses("/tf", MessageType.TF).stream().map(TopicRequests.Topic::request).toList(),
                "a throttle passes one message per interval whoever published it, a queue of one drops a burst's first");
    }

    @Test
    void aTopicOfOnePublisherIsAskedForAsItsMessagesComeUntilItSendsMoreThan50ASecond() {
        assertEquals(List.of("{\"op\":\"subscribe\",\"id\":\"wss:/gazebo/model_states\",\"topic\":\"/gazebo/model_states\","
                + "\"type\":\"gazebo_msgs/ModelStates\",\"throttle_rate\":0,\"queue_length\":0}"),
                TopicRequests.poses("/gazebo/model_states", MessageType.MODEL_STATES).stream().map(TopicRequests.Topic::request).toList(),
                "no thread of rosbridge's between: a median 13 ms less at 20 Hz against a real rosbridge");
        TopicRequests requests = new TopicRequests();
        TopicRequests.Topic odom = TopicRequests.onePublisher("/Scout/odom", MessageType.ODOMETRY);
        assertEquals(0, odom.throttleMs());
        assertEquals(0, odom.queueLength());
        requests.add(odom, 0);
        long ms = S / 1000;
        for (int i = 0; i < 100; i++) {
            assertNull(requests.came("/Scout/odom", i * 50 * ms), "20 a second for 5 s: as they come");
        }
        long start = 5 * S;
        for (int i = 0; i < TopicRequests.MOST_AS_THEY_COME; i++) {
            assertNull(requests.came("/Scout/odom", start + i * ms));
        }
        TopicRequests.Topic again = requests.came("/Scout/odom", start + 50 * ms);
        assertEquals("{\"op\":\"subscribe\",\"id\":\"wss:/Scout/odom\",\"topic\":\"/Scout/odom\",\"type\":\"nav_msgs/Odometry\","
                + "\"throttle_rate\":20,\"queue_length\":1}", again.request(), "the 51st in a second: the same id, throttled, the newest kept");
        assertNull(requests.came("/Scout/odom", start + 51 * ms), "asked for again once");
        assertFalse(requests.add(TopicRequests.onePublisher("/Scout/odom", MessageType.ODOMETRY), start), "the next poll's subscribe: kept throttled");
        TopicRequests tf = new TopicRequests();
        TopicRequests.poses("/tf", MessageType.TF).forEach(topic -> tf.add(topic, 0));
        for (int i = 0; i < 1000; i++) {
            assertNull(tf.came("/tf", i * ms), "/tf has many publishers: never throttled");
        }
    }

    @Test
    void aLatchedTopicIsAskedForAgainEvery5sUntilSomethingCameAndNeverSaidQuiet() {
        TopicRequests requests = new TopicRequests();
        TopicRequests.poses("/tf", MessageType.TF).forEach(topic -> requests.add(topic, 0));
        assertEquals(List.of(), requests.askAgain(4 * S, 5 * S));
        assertEquals(List.of("/tf_static"), requests.askAgain(5 * S, 5 * S).stream().map(TopicRequests.Topic::name).toList());
        assertEquals(List.of(), requests.askAgain(9 * S, 5 * S));
        assertEquals(List.of("/tf"), requests.quiet(9 * S, 5 * S).stream().map(TopicRequests.Topic::name).toList(),
                "/tf said quiet, /tf_static not: a graph may have no static transform");
        requests.came("/tf_static", 12 * S);
        assertEquals(List.of(), requests.askAgain(20 * S, 5 * S));
        assertFalse(requests.add(TopicRequests.onePublisher("/tf", MessageType.TF), 20 * S), "a topic is asked for once");
    }
}
