package org.usarsim.wss.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Last-Event-ID: what a stream that reconnects gets (docs/monitor.md, "GET /api/events"). */
class EventHistoryTest {

    private static List<Long> numbers(List<SseEvent> events) {
        return events.stream().map(SseEvent::number).toList();
    }

    @Test
    void anIdInTheHistoryResumesAfterItAndOneOlderOrForeignDoesNot() {
        EventHistory history = new EventHistory("run1", 3, 1 << 20);
        for (int i = 0; i < 5; i++) {
            history.append("log", "{}");
        }
        assertEquals(List.of(4L, 5L), numbers(history.after("run1-3")));
        assertEquals(List.of(3L, 4L, 5L), numbers(history.after("run1-2")), "the event after it is still kept");
        assertEquals(List.of(), numbers(history.after("run1-5")));
        assertNull(history.after("run1-1"), "event 2 is gone");
        assertNull(history.after("run1-6"), "not given yet");
        assertNull(history.after("run2-4"), "another run");
        assertNull(history.after("run1-x"));
        assertNull(history.after(null));
    }

    @Test
    void theBytesBoundTheHistoryToo() {
        EventHistory history = new EventHistory("r", 100, 200);
        for (int i = 0; i < 10; i++) {
            history.append("log", "x".repeat(50));
        }
        assertNull(history.after("r-5"));
        assertEquals(List.of(10L), numbers(history.after("r-9")));
    }

    @Test
    void afterItForgotNoEarlierIdResumesButItsLastDoes() {
        EventHistory history = new EventHistory("r", 100, 1 << 20);
        history.append("log", "{}");
        history.append("log", "{}");
        history.forget();
        assertNull(history.after("r-2"), "changes went unrecorded since");
        assertEquals(3, history.last());
        assertEquals(List.of(), numbers(history.after("r-3")), "a snapshot taken now carries id 3");
        history.append("log", "{}");
        assertEquals(List.of(4L), numbers(history.after("r-3")));
    }

    @Test
    void anEventIsOneDataLineWithItsIdAndType() {
        SseEvent event = SseEvent.of("ab", 7, "pairs", "[{\"a\":1}]");
        assertEquals("id: ab-7\nevent: pairs\ndata: [{\"a\":1}]\n\n", new String(event.wire(), java.nio.charset.StandardCharsets.UTF_8));
    }
}
