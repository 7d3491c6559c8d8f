package org.usarsim.wss.world;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.world.RosGraph.Publication;

/**
 * One rosbridge client's subscriptions, one per topic ({@link TopicSubscription}: its ids, its
 * handler), as rosbridge keeps them: made by the first subscribe op on the topic, with the op's id
 * and parameters, even when the op then fails (its type is wrong, say). Once an op on the topic
 * succeeds ({@link #connected}) the subscription is fed by the topic's publishers
 * ({@link RosGraph}): their publications strictly after that instant, or after the connection
 * delay on a per-robot topic; and each successful op delivers a latched topic's one message
 * through the handler, as rospy's {@code add_callback} does for rosbridge. What the handlers send
 * goes to the {@link TopicSubscription.Sink}, in the world's time order. Pure: the time (the
 * world's, in nanoseconds) is passed in.
 */
final class ClientSubscriptions {

    /** The most topics one client may hold subscriptions to (unknown ones included). */
    static final int MAX_TOPICS = 1000;
    /**
     * How far back publications are still delivered when the client's thread was held up (or the
     * world's time jumped, as a test's may): older ones are skipped, not sent in one burst.
     */
    static final long MAX_CATCH_UP_NANOS = 10_000_000_000L;

    /** One topic's subscription and where its publishers are. */
    private final class Feed {
        final String topic;
        final TopicSubscription<Publication> subscription;
        /** Whether its publishers reach it (an op on the topic has succeeded). */
        boolean connected;
        /** The publications after this instant are still to come. */
        long after;
        /** The next of them: at one instant (none: not connected, or nobody publishes the topic periodically). */
        List<Publication> next = List.of();

        Feed(String topic) {
            this.topic = topic;
            this.subscription = new TopicSubscription<>(sink);
        }

        void moveTo(long instant) {
            after = instant;
            next = graph.next(topic, instant);
        }

        long nextPublish() {
            return next.isEmpty() ? Long.MAX_VALUE : next.get(0).nanos();
        }
    }

    private final RosGraph graph;
    private final TopicSubscription.Sink<Publication> sink;
    private final Map<String, Feed> feeds = new LinkedHashMap<>();

    ClientSubscriptions(RosGraph graph, TopicSubscription.Sink<Publication> sink) {
        this.graph = graph;
        this.sink = sink;
    }

    /**
     * A subscribe op's id and parameters at {@code now} ({@link TopicSubscription#subscribe}); the
     * topic's subscription is made if the client had none.
     *
     * @return false when the client already has {@link #MAX_TOPICS} other topics: nothing is done
     * @throws IllegalArgumentException a queue length below 0 (rosbridge's error; the id is kept)
     */
    boolean subscribe(String topic, Object id, long throttleMs, long queueLength, long now) {
        Feed feed = feeds.get(topic);
        if (feed == null) {
            if (feeds.size() >= MAX_TOPICS) {
                return false;
            }
            feed = new Feed(topic);
            feeds.put(topic, feed);
        }
        feed.subscription.subscribe(id, throttleMs, queueLength, now);
        return true;
    }

    /**
     * A subscribe op on the topic succeeded at {@code now} (after {@link #subscribe}): from then
     * on (after the connection delay, on a per-robot topic) the topic's publishers reach the
     * subscription, if they did not already; a latched topic's message is delivered at once.
     */
    void connected(String topic, long now) {
        Feed feed = feeds.get(topic);
        if (feed == null) {
            return;
        }
        if (!feed.connected) {
            feed.connected = true;
            feed.moveTo(now + graph.startDelay(topic));
        }
        RosGraph.Publisher latched = graph.latched(topic);
        if (latched != null) {
            feed.subscription.offer(now, new Publication(latched, 0, 0));
        }
    }

    /**
     * An unsubscribe op at {@code now} ({@link TopicSubscription#unsubscribe}).
     *
     * @return false when the client had no subscription to the topic
     * @throws IllegalArgumentException as {@link #subscribe}
     */
    boolean unsubscribe(String topic, Object id, boolean all, long now) {
        Feed feed = feeds.get(topic);
        if (feed == null) {
            return false;
        }
        if (feed.subscription.unsubscribe(id, all, now)) {
            feeds.remove(topic);
        }
        return true;
    }

    /** Everything published and sent up to {@code now} (from the earliest on), sent. */
    void advance(long now) {
        for (Feed feed : feeds.values()) {
            if (feed.connected && now - feed.after > MAX_CATCH_UP_NANOS) {
                feed.moveTo(now - MAX_CATCH_UP_NANOS);
            }
        }
        while (true) {
            Feed earliest = null;
            long at = Long.MAX_VALUE;
            boolean publishes = false;
            for (Feed feed : feeds.values()) {
                long publish = feed.nextPublish();
                long send = feed.subscription.nextSend();
                if (Math.min(publish, send) < at) {
                    earliest = feed;
                    at = Math.min(publish, send);
                    publishes = publish <= send;
                }
            }
            if (earliest == null || at > now) {
                return;
            }
            if (publishes) {
                for (Publication publication : earliest.next) {
                    earliest.subscription.offer(at, publication);
                }
                earliest.moveTo(at);
            } else {
                earliest.subscription.sendDue(at);
            }
        }
    }

    /** When something is next published to or sent from a subscription; {@link Long#MAX_VALUE}: never. */
    long nextDue() {
        long next = Long.MAX_VALUE;
        for (Feed feed : feeds.values()) {
            next = Math.min(next, Math.min(feed.nextPublish(), feed.subscription.nextSend()));
        }
        return next;
    }

    /** The topics it holds subscriptions to. */
    int size() {
        return feeds.size();
    }
}
