package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Which subscriptions a tick publishes, the time moved by the test. */
class SubscriptionsTest {

    private static final long MS = 1_000_000L;

    private static List<String> due(Subscriptions subscriptions, long ms) {
        return subscriptions.due(ms * MS).stream().map(Subscriptions.Subscription::topic).toList();
    }

    @Test
    void eachAtMostOncePerItsThrottleRateTheFirstAtOnce() {
        Subscriptions subscriptions = new Subscriptions();
        subscriptions.subscribe(new Subscriptions.Subscription("/tf", "tf2_msgs/TFMessage", 200 * MS, "a"));
        subscriptions.subscribe(new Subscriptions.Subscription("/gazebo/model_states", "gazebo_msgs/ModelStates", 0, null));
        assertEquals(List.of("/tf", "/gazebo/model_states"), due(subscriptions, 0));
        assertEquals(List.of("/gazebo/model_states"), due(subscriptions, 20));
        assertEquals(List.of("/gazebo/model_states"), due(subscriptions, 180));
        assertEquals(List.of("/tf", "/gazebo/model_states"), due(subscriptions, 200));
        assertEquals(List.of("/gazebo/model_states"), due(subscriptions, 399));
        assertEquals(List.of("/tf", "/gazebo/model_states"), due(subscriptions, 400));
    }

    @Test
    void aNewSubscribeReplacesTheOldAndAnUnsubscribeEndsIt() {
        Subscriptions subscriptions = new Subscriptions();
        subscriptions.subscribe(new Subscriptions.Subscription("/tf", "tf2_msgs/TFMessage", 1000 * MS, "a"));
        assertEquals(List.of("/tf"), due(subscriptions, 0));
        subscriptions.subscribe(new Subscriptions.Subscription("/tf", "tf2_msgs/TFMessage", 50 * MS, "b"));
        assertEquals(List.of("/tf"), due(subscriptions, 20), "due at once, at its new rate");
        assertEquals(List.of(), due(subscriptions, 60));
        assertEquals(List.of("/tf"), due(subscriptions, 70));
        assertEquals(1, subscriptions.size());
        assertTrue(subscriptions.unsubscribe("/tf"));
        assertFalse(subscriptions.unsubscribe("/tf"));
        assertEquals(List.of(), due(subscriptions, 1000));
    }
}
