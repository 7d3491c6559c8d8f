package org.usarsim.wss.attach;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class EventStreamParserTest {

    private static List<EventStreamParser.Event> read(EventStreamParser parser, String stream) {
        List<EventStreamParser.Event> events = new ArrayList<>();
        for (String line : stream.split("\n", -1)) {
            EventStreamParser.Event event = parser.line(line);
            if (event != null) {
                events.add(event);
            }
        }
        return events;
    }

    @Test
    void anEventIsItsIdTypeAndDataEndedByAnEmptyLine() {
        List<EventStreamParser.Event> events = read(new EventStreamParser(), "id: 7\nevent: pair\ndata: {\"a\":1}\n\n");
        assertEquals(List.of(new EventStreamParser.Event("7", "pair", "{\"a\":1}")), events);
    }

    @Test
    void dataLinesAreJoinedByNewlinesAndOnlyOneSpaceAfterTheColonIsDropped() {
        List<EventStreamParser.Event> events = read(new EventStreamParser(), "data:one\ndata:  two\ndata\n\n");
        assertEquals(List.of(new EventStreamParser.Event(null, "message", "one\n two\n")), events);
    }

    @Test
    void commentsAndUnknownFieldsAreIgnoredAndNoEventWithoutData() {
        EventStreamParser parser = new EventStreamParser();
        assertEquals(List.of(), read(parser, ": keepalive\nevent: log\nretry: 100\n\n"));
        // The type of an event without data does not carry over to the next one.
        assertEquals(List.of(new EventStreamParser.Event(null, "message", "x")), read(parser, "data: x\n\n"));
    }

    @Test
    void theLastIdIsKeptAcrossEventsForLastEventId() {
        EventStreamParser parser = new EventStreamParser();
        List<EventStreamParser.Event> events = read(parser, "id: 3\ndata: a\n\ndata: b\n\n");
        assertEquals("3", events.get(1).id());
        assertEquals("3", parser.lastEventId());
    }

    @Test
    void anEventCutBeforeItsEmptyLineIsDropped() {
        EventStreamParser parser = new EventStreamParser();
        assertEquals(List.of(), read(parser, "id: 4\nevent: pair\ndata: half"));
        parser.reset();
        assertEquals(List.of(new EventStreamParser.Event("4", "message", "whole")), read(parser, "data: whole\n\n"));
        assertNull(new EventStreamParser().lastEventId());
    }
}
