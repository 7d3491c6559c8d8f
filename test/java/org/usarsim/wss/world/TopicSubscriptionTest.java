package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.world.TopicSubscription.Handler;

/**
 * rosbridge_library 0.11.17's rules for one client's subscription to one topic
 * (capabilities/subscribe.py, internal/subscription_modifiers.py), the time moved by the test:
 * milliseconds here, messages named for their publisher and the time they were published.
 */
class TopicSubscriptionTest {

    private static final long MS = 1_000_000L;

    /** What was sent: "message@sendTime" in ms. */
    private final List<String> sent = new ArrayList<>();
    private final TopicSubscription<String> subscription = new TopicSubscription<>((nanos, message) -> sent.add(message + "@" + nanos / MS));

    private void publish(String publisher, long ms) {
        subscription.offer(ms * MS, publisher + ms);
    }

    /** Two publishers at the same rate, A at phase 0 and B at {@code bPhase} ms, from 0 to {@code untilMs}. */
    private void twoPublishers(long periodMs, long bPhase, long untilMs) {
        for (long t = 0; t < untilMs; t += periodMs) {
            publish("A", t);
            publish("B", t + bPhase);
        }
        subscription.sendDue(untilMs * MS);
    }

    private long sentBy(String publisher) {
        return sent.stream().filter(s -> s.startsWith(publisher)).count();
    }

    @Test
    void throttleAndQueueZeroPassEveryMessageAsItComes() {
        subscription.subscribe(null, 0, 0, 0);
        assertEquals(Handler.PASS, subscription.handler());
        twoPublishers(200, 10, 1000);
        assertEquals(List.of("A0@0", "B10@10", "A200@200", "B210@210", "A400@400", "B410@410", "A600@600", "B610@610", "A800@800",
                "B810@810"), sent);
    }

    @Test
    void throttle200Queue1StarvesThePublisherJustBeforeTheOtherInPhase() {
        // the WSS's old subscription, /tf with two broadcasters at 5 Hz 10 ms apart (issue 31, fault 2)
        subscription.subscribe("wss", 200, 1, 0);
        assertEquals(Handler.QUEUE, subscription.handler());
        twoPublishers(200, 10, 5000);
        assertEquals("A0@0", sent.get(0), "the first goes at once");
        assertEquals(1, sentBy("A"), "then A's message is always evicted by B's before the send: " + sent);
        assertEquals(25, sentBy("B"));
        assertEquals("B10@200", sent.get(1), "and B's goes only at the last send + 200 ms, 190 ms late (fault 3)");
        assertEquals("B210@400", sent.get(2));
    }

    @Test
    void throttle200Queue0DropsTheOtherPublisherForGood() {
        subscription.subscribe(null, 200, 0, 0);
        assertEquals(Handler.THROTTLE, subscription.handler());
        twoPublishers(200, 10, 5000);
        assertEquals(25, sentBy("A"));
        assertEquals(0, sentBy("B"), "dropped while throttled, nothing sent later in its place: " + sent);
    }

    @Test
    void throttle200Queue1HoldsAMessageUntilTheLastSendPlus200() {
        subscription.subscribe(null, 200, 1, 0);
        publish("A", 0);
        publish("A", 50);
        assertEquals(List.of("A0@0"), sent);
        assertEquals(200 * MS, subscription.nextSend(), "held until last + T");
        publish("A", 100);
        subscription.sendDue(199 * MS);
        assertEquals(List.of("A0@0"), sent);
        subscription.sendDue(200 * MS);
        assertEquals(List.of("A0@0", "A100@200"), sent, "the newest one kept (queue of 1)");
        assertEquals(Long.MAX_VALUE, subscription.nextSend());
        publish("A", 450);
        subscription.sendDue(450 * MS);
        assertEquals(List.of("A0@0", "A100@200", "A450@450"), sent, "after an idle spell longer than T, at once");
    }

    @Test
    void aLongerQueueSendsTheOldestKeptOnePerThrottle() {
        subscription.subscribe(null, 100, 3, 0);
        for (long t = 0; t <= 200; t += 20) {
            publish("A", t);
        }
        subscription.sendDue(500 * MS);
        assertEquals(List.of("A0@0", "A40@100", "A140@200", "A160@300", "A180@400", "A200@500"), sent,
                "the oldest of the 3 newest unsent, one per 100 ms: lagging behind");
    }

    @Test
    void aQueueWithNoThrottleSendsEachAsItComes() {
        subscription.subscribe(null, 0, 1, 0);
        assertEquals(Handler.QUEUE, subscription.handler());
        publish("A", 0);
        publish("B", 0);
        subscription.sendDue(0);
        publish("A", 50);
        subscription.sendDue(50 * MS);
        assertEquals(List.of("A0@0", "B0@0", "A50@50"), sent);
    }

    @Test
    void theLeastThrottleAndTheLeastQueueOverTheIdsCount() {
        subscription.subscribe("slow", 1000, 5, 0);
        subscription.subscribe("plain", 0, 0, 0);
        assertEquals(Handler.PASS, subscription.handler(), "a plain subscribe beside {1000, 5}: min 0, 0");
        subscription.unsubscribe("plain", false, 0);
        assertArrayEquals(new long[] {1000, 5}, subscription.params(), "the plain one removed alone");
        subscription.subscribe("a", 100, 1, 0);
        subscription.subscribe("b", 500, 0, 0);
        assertArrayEquals(new long[] {100, 0}, subscription.params(), "throttle 100, queue 0: the least of each (not the most queue)");
        assertEquals(Handler.THROTTLE, subscription.handler());
    }

    @Test
    void theSameIdReplacesItsOwnAndUnsubscribeByIdOrAll() {
        subscription.subscribe("a", 1000, 0, 0);
        subscription.subscribe("a", 50, 0, 0);
        assertArrayEquals(new long[] {50, 0}, subscription.params(), "replaced, not the least with the old");
        subscription.subscribe("b", 200, 0, 0);
        assertFalse(subscription.unsubscribe("nobody", false, 0), "an unknown id: nothing");
        assertArrayEquals(new long[] {50, 0}, subscription.params());
        assertFalse(subscription.unsubscribe("a", false, 0));
        assertArrayEquals(new long[] {200, 0}, subscription.params());
        subscription.subscribe("c", 300, 0, 0);
        assertTrue(subscription.unsubscribe(null, true, 0), "no id: every id");
    }

    @Test
    void theLastSendIsKeptAcrossAChangeOfParameters() {
        subscription.subscribe("a", 200, 0, 0);
        publish("A", 0);
        subscription.subscribe("a", 500, 0, 100 * MS);
        publish("A", 300);
        publish("A", 500);
        subscription.subscribe("a", 0, 1, 600 * MS);
        publish("A", 700);
        subscription.sendDue(700 * MS);
        assertEquals(List.of("A0@0", "A500@500", "A700@700"), sent);
    }

    @Test
    void leavingTheQueueSendsWhatTheThrottleLetsGoAndDropsTheRest() {
        subscription.subscribe("a", 1000, 10, 0);
        subscription.subscribe("b", 2000, 10, 0);
        publish("A", 0);
        publish("A", 10);
        publish("A", 20);
        assertEquals(List.of("A0@0"), sent);
        subscription.subscribe("b", 0, 0, 40 * MS);
        assertEquals(List.of("A0@0", "A10@40", "A20@40"), sent, "throttle 0 first, then queue 0: all flushed");
        assertEquals(Handler.PASS, subscription.handler());

        sent.clear();
        subscription.subscribe("b", 100, 5, 100 * MS);
        for (long t = 100; t <= 130; t += 10) {
            publish("A", t);
        }
        assertTrue(subscription.unsubscribe(null, true, 345 * MS));
        assertEquals(List.of("A100@140", "A110@240", "A120@340"), sent, "the end: what the throttle let go by then; A130 dropped");
        assertEquals(Long.MAX_VALUE, subscription.nextSend());
    }

    @Test
    void aNegativeQueueLengthIsRosbridgesErrorAfterTheThrottleIsTaken() {
        subscription.subscribe("a", 500, 0, 0);
        assertThrows(IllegalArgumentException.class, () -> subscription.subscribe("b", 300, -1, 0));
        assertEquals(Handler.THROTTLE, subscription.handler(), "the queue refused");
        assertEquals(300, subscription.params()[0], "after the throttle was taken");
        assertThrows(IllegalArgumentException.class, () -> subscription.unsubscribe("a", false, 0), "b's -1 stays");
        assertTrue(subscription.unsubscribe("b", false, 0));
    }

    @Test
    void aQueueHandlerKeepsItsQueueWhenANegativeLengthIsRefused() {
        subscription.subscribe("a", 200, 2, 0);
        assertThrows(IllegalArgumentException.class, () -> subscription.subscribe("b", 100, -1, 0));
        assertEquals(Handler.QUEUE, subscription.handler());
        for (long t = 0; t <= 30; t += 10) {
            publish("A", t);
        }
        subscription.sendDue(300 * MS);
        assertEquals(List.of("A0@0", "A20@100", "A30@200"), sent, "its deque of 2, sent at the throttle of 100 taken before");
    }
}
