package org.usarsim.wss.world;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One rosbridge client's subscriptions to the topics published at the tick, and which are due
 * at a time: each at most once per its {@code throttle_rate} (0: at every tick), the first at the
 * first tick after it was made. A second subscribe to a topic replaces the first (its throttle
 * rate with it); an unsubscribe ends it whatever its id. Pure: the time is passed in.
 */
final class Subscriptions {

    /** A subscription: the topic, its type, the least time between two messages, and the client's id (or null). */
    record Subscription(String topic, String type, long throttleNanos, String id) {
    }

    private final Map<String, Subscription> byTopic = new LinkedHashMap<>();
    private final Map<String, Long> lastSent = new HashMap<>();

    void subscribe(Subscription subscription) {
        byTopic.put(subscription.topic(), subscription);
        lastSent.remove(subscription.topic());
    }

    /** Ends the subscription to a topic; false when there was none. */
    boolean unsubscribe(String topic) {
        lastSent.remove(topic);
        return byTopic.remove(topic) != null;
    }

    /** The subscriptions due at {@code nowNanos}, in the order they were made; each is then counted as sent at that time. */
    List<Subscription> due(long nowNanos) {
        List<Subscription> due = new ArrayList<>();
        for (Subscription subscription : byTopic.values()) {
            Long last = lastSent.get(subscription.topic());
            if (last == null || nowNanos - last >= subscription.throttleNanos()) {
                due.add(subscription);
                lastSent.put(subscription.topic(), nowNanos);
            }
        }
        return due;
    }

    int size() {
        return byTopic.size();
    }
}
