package org.usarsim.wss.recording;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Wall;

class RecordingReaderTest {

    @TempDir
    Path dir;

    private static String run() {
        StringBuilder text = new StringBuilder();
        EntryLines.header(text, new Header(1, "0.1.0", "2026-11-25T14:30:00Z", "ObstaclePropagationModel",
                Map.of("distance.cutoff", "-93")));
        EntryLines.write(text, new Entry.Registered(0, "A", "127.0.0.1"));
        EntryLines.write(text, new Entry.Walls(100, List.of(new Wall(0, 0, 10, 0))));
        for (int i = 1; i <= 3; i++) {
            EntryLines.write(text, new Entry.Poll(i * 200L, List.of(new ModelPoll.Robot("A", new Position(i, 0, 0), false),
                    new ModelPoll.Robot("B", new Position(10, 0, 0), false)),
                    List.of(new ModelPoll.Pair("A", "B", -60 - i, 1, i != 2))));
        }
        EntryLines.write(text, new Entry.Break(400, "A", "B", -62, 8));
        EntryLines.write(text, new Entry.Resume(600, "A", "B"));
        EntryLines.write(text, new Entry.End(650));
        return text.toString();
    }

    private Path file(String name, String text) throws Exception {
        Path file = dir.resolve(name);
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return file;
    }

    @Test
    void aWholeRecordingIsReadAsWritten() throws Exception {
        Recording recording = RecordingReader.read(file("run.rec", run()));
        assertEquals("ObstaclePropagationModel", recording.header().model());
        assertEquals("-93", recording.header().settings().get("distance.cutoff"));
        assertEquals(3, recording.polls().size());
        assertEquals(-62.0, recording.polls().get(1).pairs().get(0).strength());
        assertFalse(recording.polls().get(1).pairs().get(0).live());
        assertEquals(new Position(3, 0, 0), recording.polls().get(2).robots().get(0).position());
        assertEquals(List.of(new Wall(0, 0, 10, 0)), recording.wallsAt(650));
        assertEquals(List.of(), recording.wallsAt(99));
        assertEquals(-1, recording.pollIndexAt(199));
        assertEquals(0, recording.pollIndexAt(200));
        assertEquals(1, recording.pollIndexAt(599));
        assertEquals(650, recording.durationMillis());
        assertEquals(4, recording.events().size());
        assertEquals(java.util.Set.of("A", "B"), recording.robots());
        assertFalse(recording.cutShort());
        assertEquals(0, recording.unknownLines() + recording.unreadableLines());
    }

    @Test
    void gzipIsReadByItsName() throws Exception {
        Path file = dir.resolve("run.rec.gz");
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(file))) {
            out.write(run().getBytes(StandardCharsets.UTF_8));
        }
        assertEquals(3, RecordingReader.read(file).polls().size());
    }

    @Test
    void aGzipStreamThatStopsIsReadUpToItsLastWholeLine() throws Exception {
        Path whole = dir.resolve("whole.rec.gz");
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(whole))) {
            out.write(run().getBytes(StandardCharsets.UTF_8));
        }
        byte[] bytes = Files.readAllBytes(whole);
        Path cut = dir.resolve("cut.rec.gz");
        Files.write(cut, Arrays.copyOf(bytes, bytes.length - 12));
        Recording recording = RecordingReader.read(cut);
        assertTrue(recording.cutShort());
        assertEquals(3, recording.polls().size());
    }

    @Test
    void aRunCutShortKeepsItsWholeEntries() throws Exception {
        String text = run();
        String cutInPoll = text.substring(0, text.indexOf("600 pair"));
        Recording recording = RecordingReader.read(file("a.rec", cutInPoll));
        assertTrue(recording.cutShort());
        assertEquals(2, recording.polls().size(), "the poll missing its pair row is not replayed");
        String cutInLine = text.substring(0, text.indexOf("400 break") + 7);
        Recording midLine = RecordingReader.read(file("b.rec", cutInLine));
        assertTrue(midLine.cutShort());
        assertEquals(3, midLine.polls().size());
        assertEquals(1, midLine.events().size(), "the half-written break is dropped");
        Recording noEnd = RecordingReader.read(file("c.rec", text.substring(0, text.indexOf("650 end"))));
        assertTrue(noEnd.cutShort());
        assertEquals(0, noEnd.unreadableLines());
    }

    @Test
    void unknownAndUnreadableLinesAreSkippedAndCounted() throws Exception {
        String text = run().replace("400 break", "390 teleport A 1 2 3\n395 kick A sideways\n400 break");
        Recording recording = RecordingReader.read(file("run.rec", text));
        assertEquals(1, recording.unknownLines());
        assertEquals(1, recording.unreadableLines());
        assertTrue(recording.firstProblem().contains("teleport"), recording.firstProblem());
        assertEquals(3, recording.polls().size());
    }

    @Test
    void aPollWhoseRowsCannotBeReadHoldsThePollBefore() throws Exception {
        Recording recording = RecordingReader.read(file("run.rec", run().replace("400 pair A B -62 1 down", "400 pair A B loud 1 down")));
        assertEquals(3, recording.polls().size());
        assertEquals(400, recording.polls().get(1).millis());
        assertEquals(-61.0, recording.polls().get(1).pairs().get(0).strength());
    }

    @Test
    void whatIsNotARecordingIsRefusedInOneLine() throws Exception {
        RecordingException notOne = assertThrows(RecordingException.class,
                () -> RecordingReader.read(file("world.rec", "robot A 1,2,3\n")));
        assertTrue(notOne.getMessage().endsWith("is not a WSS recording (its first line is not WSS-RECORDING 1)"), notOne.getMessage());
        RecordingException other = assertThrows(RecordingException.class,
                () -> RecordingReader.read(file("v2.rec", "WSS-RECORDING 2\n")));
        assertTrue(other.getMessage().endsWith("is a recording of format version 2; this WSS reads version 1"), other.getMessage());
        RecordingException missing = assertThrows(RecordingException.class, () -> RecordingReader.read(dir.resolve("none.rec")));
        assertTrue(missing.getMessage().endsWith("no such file"), missing.getMessage());
        RecordingException notGzip = assertThrows(RecordingException.class,
                () -> RecordingReader.read(file("plain.rec.gz", run())));
        assertTrue(notGzip.getMessage().contains("not gzip"), notGzip.getMessage());
        assertThrows(RecordingException.class, () -> RecordingReader.read(file("empty.rec", "")));
    }
}
