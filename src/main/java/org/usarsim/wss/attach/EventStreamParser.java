package org.usarsim.wss.attach;

/**
 * Server-Sent Events ({@code text/event-stream}) read line by line, as the HTML standard's
 * "Interpreting an event stream" says: {@code data:} lines joined by newlines, {@code event:} the
 * type ({@code message} when none), {@code id:} the last event id (kept across events, for
 * {@code Last-Event-ID} on a reconnection), a line beginning with a colon a comment, one space after
 * the colon dropped, and an empty line ending the event (none dispatched without data). Pure: the
 * caller reads the lines.
 */
final class EventStreamParser {

    /** One event: its id (the last one the stream set, null before any), its type and its data. */
    record Event(String id, String type, String data) {
    }

    private final StringBuilder data = new StringBuilder();
    private boolean hasData;
    private String type = "";
    private String lastId;

    /** One line without its end; the event it completes (an empty line after data), else null. */
    Event line(String line) {
        if (line.isEmpty()) {
            return dispatch();
        }
        if (line.startsWith(":")) {
            return null;
        }
        int colon = line.indexOf(':');
        String field = colon < 0 ? line : line.substring(0, colon);
        String value = colon < 0 ? "" : line.substring(colon + 1);
        if (value.startsWith(" ")) {
            value = value.substring(1);
        }
        switch (field) {
            case "data" -> {
                if (hasData) {
                    data.append('\n');
                }
                data.append(value);
                hasData = true;
            }
            case "event" -> type = value;
            case "id" -> {
                if (value.indexOf('\0') < 0) {
                    lastId = value;
                }
            }
            default -> {
                // retry and unknown fields: ignored (the window's reconnection keeps its own pause)
            }
        }
        return null;
    }

    /** The last event id the stream set (null before any): what a reconnection sends as {@code Last-Event-ID}. */
    String lastEventId() {
        return lastId;
    }

    /** Forgets the last event id: the next connection asks for a fresh snapshot. */
    void forgetId() {
        lastId = null;
    }

    /** The stream ended (or was cut): an event not ended by its empty line is dropped, as the standard says. */
    void reset() {
        data.setLength(0);
        hasData = false;
        type = "";
    }

    private Event dispatch() {
        if (!hasData) {
            type = "";
            return null;
        }
        Event event = new Event(lastId, type.isEmpty() ? "message" : type, data.toString());
        reset();
        return event;
    }
}
