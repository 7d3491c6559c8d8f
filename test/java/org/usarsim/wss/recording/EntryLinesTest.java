package org.usarsim.wss.recording;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Wall;

class EntryLinesTest {

    @Test
    void namesWithSpacesPercentsAndControlsComeBackAsTheyWere() {
        for (String name : List.of("Alpha", "a b", "50%", "tab\there", "new\nline", "ünïcødé", "%", "\u3000wide", "a{b}")) {
            String escaped = EntryLines.escape(name);
            assertEquals(-1, escaped.indexOf(' '), escaped);
            assertEquals(-1, escaped.indexOf('\n'), escaped);
            assertEquals(name, EntryLines.unescape(escaped));
        }
        assertEquals("%", EntryLines.escape(""));
        assertEquals("", EntryLines.unescape("%"));
        assertEquals("a%20b%25", EntryLines.escape("a b%"));
        assertThrows(IllegalArgumentException.class, () -> EntryLines.unescape("a%2"));
        assertThrows(IllegalArgumentException.class, () -> EntryLines.unescape("a%zz"));
    }

    @Test
    void everyEntryIsReadBackAsWritten() {
        List<Entry> entries = List.of(
                new Entry.Registered(0, "Alpha", "127.0.0.1"),
                new Entry.Walls(10, List.of(new Wall(0, 0, 10, 0), new Wall(10, -4.5, 10.125, 14))),
                new Entry.Poll(200, List.of(new ModelPoll.Robot("Alpha", new Position(1.5, -2, 0.45), false),
                        new ModelPoll.Robot("B c", new Position(12.345, 0, 0), true)),
                        List.of(new ModelPoll.Pair("Alpha", "B c", -67.2345, 2, true),
                                new ModelPoll.Pair("Alpha", "Zed", Double.POSITIVE_INFINITY, Double.NaN, false))),
                new Entry.Kick(200, "B c", true),
                new Entry.Kick(400, "Zed", false),
                new Entry.Break(400, "Alpha", "B c", -95.5, 31.25),
                new Entry.Resume(600, "Alpha", "B c"),
                new Entry.Force(700, "Alpha", "B c", true),
                new Entry.Force(701, "Alpha", "B c", false),
                new Entry.Pin(750, "Alpha", "B c", 1_000_000, 50, 20),
                new Entry.Pin(751, "Alpha", "B c", 0, -1, 0),
                new Entry.Release(800, "Alpha", "B c"),
                new Entry.Rate(900, "Alpha", "B c", 54_000_000),
                new Entry.Udp(920, "B c", "Alpha", 17400, 1200, 1_680_000, 3, 2, 14),
                new Entry.Dropped(950, 12),
                new Entry.Left(1000, "Alpha"),
                new Entry.End(1001));
        StringBuilder text = new StringBuilder();
        entries.forEach(entry -> EntryLines.write(text, entry));
        List<Entry> read = new ArrayList<>();
        List<EntryLines.Line> group = new ArrayList<>();
        for (String line : text.toString().split("\n")) {
            EntryLines.Line parsed = EntryLines.read(line);
            if (parsed instanceof EntryLines.Whole whole) {
                read.add(whole.entry());
            } else {
                group.add(parsed);
            }
        }
        assertEquals(entries.stream().filter(e -> !(e instanceof Entry.Poll || e instanceof Entry.Walls)).toList(), read);
        assertEquals(new EntryLines.WallsHead(10, 2), group.get(0));
        assertEquals(new EntryLines.WallRow(10, new Wall(10, -4.5, 10.125, 14)), group.get(2));
        assertEquals(new EntryLines.PollHead(200, 2, 2), group.get(3));
        assertEquals(new EntryLines.RobotRow(200, new ModelPoll.Robot("B c", new Position(12.345, 0, 0), true)), group.get(5));
        EntryLines.PairRow pair = assertInstanceOf(EntryLines.PairRow.class, group.get(6));
        assertEquals(-67.2345, pair.pair().strength());
        EntryLines.PairRow infinite = assertInstanceOf(EntryLines.PairRow.class, group.get(7));
        assertEquals(Double.POSITIVE_INFINITY, infinite.pair().strength());
        assertEquals(Double.NaN, infinite.pair().obstacles());
    }

    /** Issue 36: a udp line says its fixed port; a line of a recording made before (no port) is still read, its port not known. */
    @Test
    void aUdpLineSaysItsPortAndAnOlderOneWithoutIsStillRead() {
        StringBuilder text = new StringBuilder();
        EntryLines.write(text, new Entry.Udp(920, "Scout", "Base", 17400, 10, 20, 0, 0, 0));
        assertEquals("920 udp Scout Base 17400 10 20 0 0 0\n", text.toString());
        assertEquals(new EntryLines.Whole(new Entry.Udp(920, "Scout", "Base", Entry.Udp.NO_PORT, 10, 20, 0, 0, 0)),
                EntryLines.read("920 udp Scout Base 10 20 0 0 0"));
        for (String line : List.of("920 udp Scout Base 0 10 20 0 0 0", "920 udp Scout Base 65536 10 20 0 0 0", "920 udp Scout Base 10 20 0 0",
                "920 udp Scout Base 1 10 20 0 0 0 0")) {
            assertThrows(IllegalArgumentException.class, () -> EntryLines.read(line), line);
        }
    }

    /** Issue 35: a wall's material is a fifth field; a wall without one is written and read as before. */
    @Test
    void aWallsMaterialIsAFifthFieldAndAWallWithoutOneIsWrittenAsBefore() {
        StringBuilder text = new StringBuilder();
        EntryLines.write(text, new Entry.Walls(10, List.of(new Wall(0, 0, 10, 0), new Wall(1, 2, 3, 4, "glass"))));
        assertEquals("10 walls 2\n10 wall 0 0 10 0\n10 wall 1 2 3 4 glass\n", text.toString());
        assertEquals(new EntryLines.WallRow(10, new Wall(0, 0, 10, 0, "")), EntryLines.read("10 wall 0 0 10 0"));
        assertEquals(new EntryLines.WallRow(10, new Wall(1, 2, 3, 4, "glass")), EntryLines.read("10 wall 1 2 3 4 glass"));
        assertThrows(IllegalArgumentException.class, () -> EntryLines.read("10 wall 1 2 3 4 glass more"));
    }

    @Test
    void aStrengthIsWrittenAsGetssAnswersIt() {
        StringBuilder text = new StringBuilder();
        EntryLines.write(text, new Entry.Poll(5, List.of(), List.of(new ModelPoll.Pair("A", "B", -67.23456789, 0, true))));
        assertEquals("5 poll 0 1\n5 pair A B -67.2346 0 up\n", text.toString());
    }

    @Test
    void theHeaderIsItsOwnLines() {
        StringBuilder text = new StringBuilder();
        EntryLines.header(text, new Header(1, "0.1.0", "2026-11-25T14:30:00Z", "ObstaclePropagationModel",
                Map.of("replay.file", "/tmp/a b.rec")));
        assertEquals("WSS-RECORDING 1\nwss 0.1.0\nstarted 2026-11-25T14:30:00Z\nmodel ObstaclePropagationModel\n"
                + "setting replay.file /tmp/a%20b.rec\n", text.toString());
    }

    @Test
    void aBrokenLineSaysWhatIsWrong() {
        for (String line : List.of("x poll 1 1", "5", "5  poll 1 1", "5 robot A 1 2 ok", "5 robot A 1 2 3 maybe",
                "5 pair A B -60 - sideways", "5 kick A because", "-5 end", "5 robot A 1 NaN 3 ok", "5 rate A B fast")) {
            assertThrows(IllegalArgumentException.class, () -> EntryLines.read(line), line);
        }
        assertEquals(new EntryLines.Unknown(5, "teleport"), EntryLines.read("5 teleport A 1 2 3"));
    }
}
