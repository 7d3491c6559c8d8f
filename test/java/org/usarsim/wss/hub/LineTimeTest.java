package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.time.ZoneId;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The event log's time of day, against the formatter it stands for. */
class LineTimeTest {

    private static final DateTimeFormatter LINE = DateTimeFormatter.ofPattern("HH:mm:ss.SSS");

    private static void assertAsTheFormatter(ZoneId zone, long... millis) {
        LineTime time = new LineTime(zone);
        for (long at : millis) {
            StringBuilder text = new StringBuilder();
            time.append(text, at);
            assertEquals(LINE.format(Instant.ofEpochMilli(at).atZone(zone)), text.toString(), "at " + at + " in " + zone);
        }
    }

    @Test
    void everyMillisecondOfTwoSecondsInTurnAndBack() {
        long start = ZonedDateTime.of(2026, 11, 27, 23, 59, 59, 0, ZoneId.of("UTC")).toInstant().toEpochMilli();
        long[] millis = new long[4000];
        for (int i = 0; i < 2000; i++) {
            millis[i] = start + i;
            millis[2000 + i] = start + 1999 - i; // backwards: a clock set back
        }
        assertAsTheFormatter(ZoneId.of("UTC"), millis);
    }

    @Test
    void aroundTheChangesOfSummerTimeAndInZonesOfOddOffsets() {
        ZoneId berlin = ZoneId.of("Europe/Berlin");
        long spring = ZonedDateTime.of(2026, 3, 29, 1, 59, 59, 0, berlin).toInstant().toEpochMilli();
        long autumn = ZonedDateTime.of(2026, 10, 25, 2, 59, 59, 0, berlin).toInstant().toEpochMilli();
        assertAsTheFormatter(berlin, spring, spring + 999, spring + 1000, spring + 1001, autumn - 3_600_000, autumn, autumn + 1000,
                autumn + 3_601_000);
        assertAsTheFormatter(ZoneId.of("Asia/Kathmandu"), 0, 1, 999, 1000, 1_790_000_000_123L);
        // Amsterdam before 1937 was 00:19:32 ahead of UTC: an offset of whole seconds, not minutes.
        assertAsTheFormatter(ZoneId.of("Europe/Amsterdam"), -1_500_000_000_001L, -1_500_000_000_000L, -1_499_999_999_999L);
    }

    @Test
    void manyRandomTimesInTheMachinesZone() {
        Random random = new Random(27);
        long[] millis = new long[10_000];
        for (int i = 0; i < millis.length; i++) {
            millis[i] = random.nextLong() % 4_000_000_000_000L;
        }
        assertAsTheFormatter(ZoneId.systemDefault(), millis);
    }
}
