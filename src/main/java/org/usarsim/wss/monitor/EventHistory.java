package org.usarsim.wss.monitor;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * The events of the run, numbered from 1, the last ones kept (at most {@code maxEvents} and
 * {@code maxBytes}) so that a stream that reconnects with {@code Last-Event-ID} gets what it
 * missed ({@link #after}); an id older than what is kept, of another run or not one at all gets
 * null: the stream starts with a snapshot instead. Pure; one thread (the publisher's) at a time.
 */
final class EventHistory {

    static final int MAX_EVENTS = 4096;
    static final long MAX_BYTES = 16L * 1024 * 1024;

    private final String run;
    private final int maxEvents;
    private final long maxBytes;
    private final ArrayDeque<SseEvent> kept = new ArrayDeque<>();
    private long bytes;
    private volatile long last;
    /** Every event numbered above this one is kept. */
    private long complete;

    EventHistory(String run, int maxEvents, long maxBytes) {
        this.run = run;
        this.maxEvents = maxEvents;
        this.maxBytes = maxBytes;
    }

    String run() {
        return run;
    }

    /** The number of the last event (0 before the first). */
    long last() {
        return last;
    }

    SseEvent append(String type, String json) {
        SseEvent event = SseEvent.of(run, ++last, type, json);
        kept.addLast(event);
        bytes += event.wire().length;
        while (kept.size() > maxEvents || (bytes > maxBytes && kept.size() > 1)) {
            SseEvent gone = kept.removeFirst();
            bytes -= gone.wire().length;
            complete = gone.number();
        }
        return event;
    }

    /**
     * The events after the one of that id, or null when they are not all kept (the id is older than
     * the history, of another run, of a number not given yet, or not an id of this server).
     */
    List<SseEvent> after(String lastEventId) {
        if (lastEventId == null || !lastEventId.startsWith(run + "-")) {
            return null;
        }
        long number;
        try {
            number = Long.parseLong(lastEventId.substring(run.length() + 1));
        } catch (NumberFormatException e) {
            return null;
        }
        if (number < complete || number > last) {
            return null;
        }
        List<SseEvent> missed = new ArrayList<>();
        for (SseEvent event : kept) {
            if (event.number() > number) {
                missed.add(event);
            }
        }
        return missed;
    }

    /**
     * Forgets every event (no stream listened, so changes went unrecorded): no id given so far can
     * resume. A number is skipped so that the last one given is past the history too.
     */
    void forget() {
        kept.clear();
        bytes = 0;
        last++;
        complete = last;
    }
}
