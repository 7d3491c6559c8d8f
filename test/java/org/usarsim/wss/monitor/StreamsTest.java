package org.usarsim.wss.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** A viewer that does not read: its bounded queue fills, it is cut and counted, the others go on; publishing never waits. */
class StreamsTest {

    @Test
    void aStreamWhoseQueueFillsIsCutAndTheOthersKeepTheirEvents() throws Exception {
        Streams streams = new Streams(4);
        assertTrue(streams.reserve());
        assertTrue(streams.reserve());
        EventStream stuck = new EventStream(null, "stuck", streams::release);
        EventStream reading = new EventStream(null, "reading", streams::release);
        streams.listen(stuck);
        streams.listen(reading);
        for (int i = 0; i < EventStream.MAX_QUEUED; i++) {
            streams.publish(SseEvent.of("r", i + 1, "log", "{}"));
            if (i % 100 == 0) {
                reading.take();
            }
        }
        assertEquals(0, streams.cut());
        reading.take();
        streams.publish(SseEvent.of("r", EventStream.MAX_QUEUED + 1, "log", "{}"));
        assertEquals(1, streams.cut());
        assertEquals(EventStream.MAX_QUEUED + 1, streams.dropped(), "its queue and the event that did not fit");
        assertFalse(stuck.offer(SseEvent.of("r", 9999, "log", "{}")), "cut: no more");
        assertTrue(reading.offer(SseEvent.of("r", 9999, "log", "{}")));
    }

    @Test
    void theBytesBoundTheQueueButAFirstEventOfAnySizeIsTaken() {
        EventStream stream = new EventStream(null, "v", s -> { });
        byte[] big = new byte[(int) EventStream.MAX_QUEUED_BYTES + 1];
        assertTrue(stream.offer(new SseEvent(1, "snapshot", big)));
        assertFalse(stream.offer(SseEvent.of("r", 2, "log", "{}")));
    }

    @Test
    void slotsStopAtMaxAndComeBackWhenAStreamEnds() {
        Streams streams = new Streams(1);
        assertTrue(streams.reserve());
        assertFalse(streams.reserve());
        streams.release(null);
        assertTrue(streams.reserve());
    }
}
