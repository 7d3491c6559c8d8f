package org.usarsim.wss.world;

import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.Map;

/**
 * One client's subscription to one topic as rosbridge_library 0.11.17 has it: which of the
 * topic's messages are sent, and when. Each {@code subscribe} op adds its {@code id}'s
 * throttle_rate and queue_length (the same id replaces its own; no id is an id too), and the
 * subscription takes the <em>least</em> of each over its ids (capabilities/subscribe.py,
 * {@code Subscription.update_params}: both min, whatever ROSBRIDGE_PROTOCOL.md says of
 * queue_length). They choose the handler (internal/subscription_modifiers.py):
 * <ul>
 * <li>{@link Handler#PASS} (throttle 0, queue 0): every message sent as it comes;</li>
 * <li>{@link Handler#THROTTLE} (throttle T, queue 0): a message sent if T has passed since the
 * last send, otherwise dropped for good (nothing is sent later in its place);</li>
 * <li>{@link Handler#QUEUE} (queue N above 0, any T): the N newest unsent messages kept (a full
 * queue drops its oldest), and the oldest kept sent as soon as T has passed since the last send.</li>
 * </ul>
 * A message is a message, whoever published it: the throttle and the queue do not tell
 * publishers apart. The last send's time is kept across every change of the parameters; before
 * the first it is long ago. Pure: the time (the world's, in nanoseconds) is passed in, and what
 * is sent goes to the {@link Sink} with the time it is sent at, in order.
 *
 * @param <M> a message
 */
final class TopicSubscription<M> {

    /** Where sent messages go. */
    interface Sink<M> {
        void send(long nanos, M message);
    }

    /** rosbridge_library's three message handlers. */
    enum Handler {
        PASS, THROTTLE, QUEUE
    }

    /** One id's parameters: throttle_rate in ms and queue_length, as the op gave them. */
    private record Params(long throttleMs, long queueLength) {
    }

    /** A throttle_rate beyond this many ms (31 years) is taken as this. */
    static final long MAX_THROTTLE_MS = 1_000_000_000_000L;
    /** The time of the send before the first: rosbridge's 0, the epoch, long before the world started. */
    private static final long NEVER = Long.MIN_VALUE / 4;

    private final Map<Object, Params> byId = new HashMap<>();
    private final Sink<M> sink;
    private Handler handler = Handler.PASS;
    /** The handler's throttle rate and queue length, as rosbridge's handler object holds them (set one at a time). */
    private long throttleNanos;
    private long queueLength;
    private final ArrayDeque<M> queue = new ArrayDeque<>();
    /** The queue's bound, set when the queue handler's deque is made (its {@code maxlen}). */
    private int capacity;
    /** When the queue last became non-empty, or was last sent from, or its handler was told of a change. */
    private long readySince;
    private long lastSend = NEVER;

    TopicSubscription(Sink<M> sink) {
        this.sink = sink;
    }

    /**
     * A subscribe op at {@code now}: its id's parameters (replacing that id's own), then the
     * handler for the least of each over every id.
     *
     * @param id the op's id, null without one
     * @throws IllegalArgumentException the least queue_length is below 0: rosbridge's
     *         {@code deque(maxlen=...)} throws, after the throttle rate has been taken; the id is kept
     */
    void subscribe(Object id, long throttleMs, long queueLength, long now) {
        sendDue(now);
        byId.put(id, new Params(Math.max(-MAX_THROTTLE_MS, Math.min(MAX_THROTTLE_MS, throttleMs)), queueLength));
        updateParams(now);
    }

    /**
     * An unsubscribe op at {@code now}: that id's parameters gone (an unknown id: nothing), or every
     * id's ({@code all}: the op had no id). When none is left the subscription ends: a queue
     * handler sends what its throttle lets it send at once (all with throttle 0, at most one
     * otherwise) and drops the rest, as rosbridge's {@code finish} does.
     *
     * @return true when the subscription ended
     * @throws IllegalArgumentException as {@link #subscribe}, when ids are left
     */
    boolean unsubscribe(Object id, boolean all, long now) {
        sendDue(now);
        if (all) {
            byId.clear();
        } else {
            byId.remove(id);
        }
        if (byId.isEmpty()) {
            finish(now);
            return true;
        }
        updateParams(now);
        return false;
    }

    /** A message of the topic, published at {@code nanos} (not before any earlier one). */
    void offer(long nanos, M message) {
        sendDue(nanos);
        switch (handler) {
            case PASS -> send(nanos, message);
            case THROTTLE -> {
                if (nanos >= lastSend + throttleNanos) {
                    send(nanos, message);
                }
            }
            case QUEUE -> {
                if (queue.isEmpty()) {
                    readySince = nanos;
                }
                if (queue.size() >= capacity) {
                    queue.removeFirst();
                }
                queue.addLast(message);
            }
        }
    }

    /** Sends what the queue handler sends up to {@code now} (a message published at the same instant as a send comes after it). */
    void sendDue(long now) {
        while (handler == Handler.QUEUE && !queue.isEmpty()) {
            long at = Math.max(lastSend + throttleNanos, readySince);
            if (at > now) {
                return;
            }
            readySince = at;
            send(at, queue.removeFirst());
        }
    }

    /** When the queue handler sends next; {@link Long#MAX_VALUE} when it has nothing to send. */
    long nextSend() {
        return handler == Handler.QUEUE && !queue.isEmpty() ? Math.max(lastSend + throttleNanos, readySince) : Long.MAX_VALUE;
    }

    Handler handler() {
        return handler;
    }

    /** The least throttle rate and queue length over its ids, as {@code {ms, length}}. */
    long[] params() {
        return new long[] {throttleNanos / 1_000_000L, queueLength};
    }

    private void send(long nanos, M message) {
        lastSend = nanos;
        sink.send(nanos, message);
    }

    /** {@code update_params}: the throttle rate set, then the queue length, each choosing the handler. */
    private void updateParams(long now) {
        long throttleMs = byId.values().stream().mapToLong(Params::throttleMs).min().orElseThrow();
        long length = byId.values().stream().mapToLong(Params::queueLength).min().orElseThrow();
        throttleNanos = throttleMs * 1_000_000L;
        transition(now);
        queueLength = length;
        transition(now);
    }

    /** {@code transition()}: the handler the handler's parameters ask for. */
    private void transition(long now) {
        Handler next = throttleNanos == 0 && queueLength == 0 ? Handler.PASS : queueLength == 0 ? Handler.THROTTLE : Handler.QUEUE;
        if (next == Handler.QUEUE && queueLength < 0) {
            throw new IllegalArgumentException("maxlen must be non-negative");
        }
        if (next == Handler.QUEUE) {
            capacity = (int) Math.min(queueLength, Integer.MAX_VALUE);
            while (queue.size() > capacity) {
                queue.removeFirst();
            }
            readySince = now; // its thread is told (or started), and sends at once if the throttle lets it
        } else if (handler == Handler.QUEUE) {
            finish(now);
        }
        handler = next;
    }

    /** A queue handler's end: what the throttle lets go now is sent, the rest dropped. */
    private void finish(long now) {
        while (handler == Handler.QUEUE && !queue.isEmpty() && now >= lastSend + throttleNanos) {
            send(now, queue.removeFirst());
        }
        queue.clear();
    }
}
