package org.usarsim.wss.hub;

import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;

/**
 * The time of day of an event log line, {@code HH:mm:ss.SSS} in a zone, as
 * {@code DateTimeFormatter.ofPattern("HH:mm:ss.SSS")} writes it. A busy link makes thousands of
 * lines a second: the formatter is asked once a second and the milliseconds appended. One
 * thread's (the log's writer): it remembers the last second.
 */
final class LineTime {

    private static final DateTimeFormatter SECOND = DateTimeFormatter.ofPattern("HH:mm:ss.");

    private final ZoneId zone;
    private long second = Long.MIN_VALUE;
    private String secondText;

    LineTime(ZoneId zone) {
        this.zone = zone;
    }

    /** Appends the time of day of {@code millis} (since the epoch). */
    void append(StringBuilder text, long millis) {
        long now = Math.floorDiv(millis, 1000);
        if (now != second) {
            secondText = SECOND.format(Instant.ofEpochSecond(now).atZone(zone));
            second = now;
        }
        int milli = (int) Math.floorMod(millis, 1000);
        text.append(secondText).append((char) ('0' + milli / 100)).append((char) ('0' + milli / 10 % 10)).append((char) ('0' + milli % 10));
    }
}
