package org.usarsim.wss.monitor;

import java.nio.charset.StandardCharsets;

/**
 * One Server-Sent Event as the wire carries it, written once and shared by every stream: its
 * number in the run, its type and its whole text ({@code id:}, {@code event:}, one {@code data:}
 * line of JSON, the blank line).
 */
record SseEvent(long number, String type, byte[] wire) {

    static SseEvent of(String run, long number, String type, String json) {
        String text = "id: " + id(run, number) + "\nevent: " + type + "\ndata: " + json + "\n\n";
        return new SseEvent(number, type, text.getBytes(StandardCharsets.UTF_8));
    }

    /** The id a client sends back as Last-Event-ID: the run, a dash, the number. */
    static String id(String run, long number) {
        return run + "-" + number;
    }
}
