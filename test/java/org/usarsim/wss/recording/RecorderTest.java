package org.usarsim.wss.recording;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.StuckWriter;
import org.usarsim.wss.Version;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Wall;

/** The recorder with a clock the test moves: what it writes, when, and what it does when it cannot keep up. */
@Timeout(30)
class RecorderTest {

    private static final Instant STARTED = Instant.parse("2026-11-25T14:30:00.123Z");
    private static final long MS = 1_000_000L;
    private static final List<Wall> ROOM = List.of(new Wall(0, 0, 10, 0), new Wall(10, 0, 10, 8.5));

    @TempDir
    Path dir;

    /** The clock: nanoseconds, moved by the test. */
    private final AtomicLong now = new AtomicLong(5_000 * MS);
    private final List<String> logged = new CopyOnWriteArrayList<>();
    private final Logger log = Logger.getLogger(Recorder.class.getName());
    private final Handler handler = new Handler() {
        @Override
        public void publish(LogRecord record) {
            logged.add(record.getLevel() + " " + record.getMessage());
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    };

    @BeforeEach
    void listen() {
        log.addHandler(handler);
    }

    @AfterEach
    void stopListening() {
        log.removeHandler(handler);
    }

    private Recorder recorder(Path file) throws IOException {
        Map<String, String> settings = new LinkedHashMap<>();
        settings.put("usarsim.interval", "200");
        settings.put("distance.cutoff", "-93");
        settings.put("wss.shaping", "off");
        return Recorder.create(file, "ObstaclePropagationModel", settings, STARTED, now::get, Recorder.QUEUE_CAPACITY);
    }

    private void at(long millis) {
        now.set(5_000 * MS + millis * MS);
    }

    private static ModelPoll poll(double alphaX, List<ModelPoll.Kick> kicks, List<Wall> walls) {
        return new ModelPoll(List.of(new ModelPoll.Robot("Alpha", new Position(alphaX, -2, 0.45), false),
                new ModelPoll.Robot("Bravo", new Position(12.345, 0, 0), true)), kicks,
                List.of(new ModelPoll.Pair("Alpha", "Bravo", -67.2345, 2, true)), walls);
    }

    /** Issue 26, item 7: the window's Record path is said as a plain path, not /some/dir/./run-....rec. */
    @Test
    void aRunFileInTheCurrentFolderIsNamedWithoutADot() {
        Path file = Recorder.runFileIn(Path.of("/some/dir/."));
        assertEquals(Path.of("/some/dir"), file.getParent());
        assertTrue(file.getFileName().toString().matches("run-\\d{4}\\.\\d{2}\\.\\d{2}-\\d{2}\\.\\d{2}\\.\\d{2}\\.\\d{3}\\.rec"), file.toString());
    }

    @Test
    void writesTheHeaderAndEveryEntryAtItsTimeFromTheStart() throws Exception {
        Path file = dir.resolve("run.rec");
        Recorder recorder = recorder(file);
        assertEquals(file, recorder.file());
        assertTrue(logged.isEmpty(), "said once the run has started, not before: " + logged);
        recorder.started();
        assertTrue(logged.contains("INFO recording the run to " + file.toAbsolutePath()), logged.toString());
        at(0);
        recorder.robotRegistered("Alpha", "127.0.0.1", List.of(5000));
        at(12);
        recorder.robotRegistered("Bravo", "127.0.0.2", List.of());
        at(200);
        recorder.polled(poll(1.5, List.of(), ROOM));
        at(400);
        recorder.polled(poll(2.5, List.of(new ModelPoll.Kick("Zed", false)), ROOM)); // the same walls: not written again
        recorder.connectionOutOfRange("Alpha", "Bravo", -95.5, 31.25);
        at(600);
        recorder.polled(poll(3.5, List.of(), List.of(new Wall(1, 1, 2, 2))));
        recorder.connectionInRange("Alpha", "Bravo");
        at(700);
        recorder.pairForced("Alpha", "Bravo", false);
        recorder.dataSent("Alpha", "Bravo", 1000); // never recorded
        recorder.portListening("Alpha", "Bravo", 5000, 40000, false); // never recorded
        at(800);
        recorder.pairReleased("Alpha", "Bravo");
        at(900);
        recorder.rateChanged("Alpha", "Bravo", 54_000_000);
        at(1000);
        recorder.robotDeregistered("Alpha");
        at(1234);
        recorder.close();
        recorder.robotDeregistered("Bravo"); // after the end: ignored
        recorder.close(); // twice: nothing more

        Recording recording = RecordingReader.read(file);
        Header header = recording.header();
        assertEquals(EntryLines.VERSION, header.version());
        assertEquals(Version.current(), header.wssVersion());
        assertEquals("2026-11-25T14:30:00.123Z", header.started());
        assertEquals("ObstaclePropagationModel", header.model());
        assertEquals(List.of("usarsim.interval=200", "distance.cutoff=-93", "wss.shaping=off"),
                header.settings().entrySet().stream().map(Object::toString).toList());
        assertEquals(List.of(
                new Entry.Registered(0, "Alpha", "127.0.0.1"),
                new Entry.Registered(12, "Bravo", "127.0.0.2"),
                new Entry.Kick(400, "Zed", false),
                new Entry.Break(400, "Alpha", "Bravo", -95.5, 31.25),
                new Entry.Resume(600, "Alpha", "Bravo"),
                new Entry.Force(700, "Alpha", "Bravo", false),
                new Entry.Release(800, "Alpha", "Bravo"),
                new Entry.Rate(900, "Alpha", "Bravo", 54_000_000),
                new Entry.Left(1000, "Alpha"),
                new Entry.End(1234)), recording.events());
        assertEquals(List.of(200L, 400L, 600L), recording.polls().stream().map(Entry.Poll::millis).toList());
        assertEquals(new Entry.Poll(400, poll(2.5, List.of(), List.of()).robots(), poll(2.5, List.of(), List.of()).pairs()),
                recording.polls().get(1));
        assertEquals(List.of(new Entry.Walls(200, ROOM), new Entry.Walls(600, List.of(new Wall(1, 1, 2, 2)))), recording.walls());
        assertFalse(recording.cutShort());
        assertEquals(0, recording.unknownLines() + recording.unreadableLines());
        assertEquals(1234, recording.durationMillis());
        // The kick comes before its poll, the walls between them, the poll's rows right after it.
        List<String> lines = Files.readAllLines(file);
        int kick = lines.indexOf("400 kick Zed absent");
        assertEquals("400 poll 2 1", lines.get(kick + 1));
        assertEquals(List.of("200 walls 2", "200 wall 0 0 10 0", "200 wall 10 0 10 8.5", "200 poll 2 1",
                "200 robot Alpha 1.5 -2 0.45 ok", "200 robot Bravo 12.345 0 0 empty", "200 pair Alpha Bravo -67.2345 2 up"),
                lines.subList(lines.indexOf("200 walls 2"), lines.indexOf("200 walls 2") + 7));
    }

    @Test
    void aNameEndingInGzIsAWholeGzipFileTheReaderReads() throws Exception {
        Path file = dir.resolve("run.rec.gz");
        Recorder recorder = recorder(file);
        at(5);
        recorder.robotRegistered("a b", "127.0.0.1", List.of());
        at(200);
        recorder.polled(poll(1, List.of(), ROOM));
        at(300);
        recorder.close();
        try (InputStream in = Files.newInputStream(file)) {
            assertArrayEquals(new byte[] {0x1f, (byte) 0x8b}, in.readNBytes(2), "gzip");
        }
        Recording recording = RecordingReader.read(file);
        assertFalse(recording.cutShort(), "the gzip stream is whole and ends with end");
        assertEquals(List.of(new Entry.Registered(5, "a b", "127.0.0.1"), new Entry.End(300)), recording.events());
        assertEquals(1, recording.polls().size());
        assertEquals(ROOM, recording.wallsAt(200));
    }

    @Test
    void aGzipRecordingIsReadableWhileItIsWritten() throws Exception {
        Path file = dir.resolve("live.rec.gz");
        Recorder recorder = recorder(file);
        at(5);
        recorder.robotRegistered("Alpha", "127.0.0.1", List.of());
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        String text = "";
        while (!text.contains("5 register Alpha 127.0.0.1\n") && System.nanoTime() < deadline) {
            Thread.sleep(10);
            text = gunzippedSoFar(file);
        }
        assertTrue(text.startsWith("WSS-RECORDING 1\n") && text.endsWith("5 register Alpha 127.0.0.1\n"),
                "flushed once caught up: " + text);
        recorder.close();
    }

    /** What a gzip file that is still being written holds so far. */
    private static String gunzippedSoFar(Path file) throws IOException {
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        try (InputStream in = new GZIPInputStream(Files.newInputStream(file))) {
            byte[] buffer = new byte[4096];
            int n;
            while ((n = in.read(buffer)) > 0) {
                text.write(buffer, 0, n);
            }
        } catch (EOFException e) {
            // the stream goes on: what it has so far is in text
        }
        return text.toString(StandardCharsets.UTF_8);
    }

    /** Issue 36, item 9: a run that did not start leaves no recording and says none. */
    @Test
    void aDiscardedRecordingLeavesNoFileAndNeverSaidWhereItRecorded() throws Exception {
        Path kept = Files.writeString(dir.resolve("run.rec"), "keep me\n");
        Recorder recorder = recorder(kept);
        recorder.robotRegistered("Alpha", "127.0.0.1", List.of(5000));
        assertTrue(Files.exists(recorder.file()));
        recorder.discard();
        assertFalse(Files.exists(recorder.file()), "the new file is deleted");
        assertEquals("keep me\n", Files.readString(kept), "the one asked for, which existed, is kept");
        assertEquals(List.of(), logged);
        recorder.robotRegistered("Bravo", "127.0.0.1", List.of(5000));
        assertFalse(Files.exists(recorder.file()), "nothing written after");
    }

    @Test
    void neverOverwritesAFileTheNewOneGetsTheStartTimeInItsName() throws Exception {
        Path file = Files.writeString(dir.resolve("run.rec"), "keep me\n");
        String time = DateTimeFormatter.ofPattern("yyyy.MM.dd-HH.mm.ss").format(STARTED.atZone(ZoneId.systemDefault()));
        Recorder first = recorder(file);
        first.started();
        first.close();
        Recorder second = recorder(file);
        second.close();
        assertEquals("keep me\n", Files.readString(file));
        assertEquals(dir.resolve("run-" + time + ".rec"), first.file());
        assertEquals(dir.resolve("run-" + time + "-2.rec"), second.file());
        assertTrue(logged.contains("INFO recording the run to " + first.file().toAbsolutePath() + " (run.rec exists: it is kept)"),
                logged.toString());
        assertEquals(List.of(new Entry.End(0)), RecordingReader.read(first.file()).events());

        Instant started = STARTED;
        assertEquals(dir.resolve("run-" + time + ".rec.gz"), Recorder.freeName(dir.resolve("run.rec.gz"), started, 1));
        assertEquals(dir.resolve("my.run-" + time + ".rec"), Recorder.freeName(dir.resolve("my.run.rec"), started, 1));
        assertEquals(dir.resolve("run-" + time), Recorder.freeName(dir.resolve("run"), started, 1));
        assertEquals(dir.resolve(".rec-" + time), Recorder.freeName(dir.resolve(".rec"), started, 1));
        assertEquals(dir.resolve("run-" + time + "-3.gz"), Recorder.freeName(dir.resolve("run.gz"), started, 3));
    }

    @Test
    void aMissingFolderIsCreated() throws Exception {
        Path file = dir.resolve("runs/today/run.rec");
        recorder(file).close();
        assertEquals(List.of(new Entry.End(0)), RecordingReader.read(file).events());
    }

    @Test
    void aFullQueueIsCountedAsDroppedAndNeverStallsTheCaller() throws Exception {
        StuckWriter out = new StuckWriter();
        Recorder recorder = new Recorder(dir.resolve("slow.rec"), out, now::get, 8);
        long before = System.nanoTime();
        for (int i = 0; i < 1000; i++) {
            at(i);
            recorder.robotRegistered("r" + i, "127.0.0.1", List.of());
        }
        long tookMs = (System.nanoTime() - before) / MS;
        assertTrue(tookMs < 2000, "1,000 events offered to a writer that cannot write in " + tookMs + " ms");
        out.release.countDown();
        at(5000);
        recorder.close();
        List<Entry> entries = new ArrayList<>();
        for (String line : out.text.toString().split("\n")) {
            entries.add(((EntryLines.Whole) EntryLines.read(line)).entry());
        }
        long registered = entries.stream().filter(e -> e instanceof Entry.Registered).count();
        long dropped = entries.stream().filter(e -> e instanceof Entry.Dropped).mapToLong(e -> ((Entry.Dropped) e).count()).sum();
        assertTrue(dropped > 0, "some were dropped: " + entries.size() + " entries");
        assertEquals(1000, registered + dropped, "every event is written or counted");
        assertEquals(new Entry.End(5000), entries.get(entries.size() - 1));
    }

    @Test
    void manyPollsQueuedAreDroppedBeforeTheyFillTheMemory() throws Exception {
        StuckWriter out = new StuckWriter();
        Recorder recorder = new Recorder(dir.resolve("slow.rec"), out, now::get, Recorder.QUEUE_CAPACITY);
        int polls = Recorder.MAX_QUEUED_POLLS + 100;
        for (int i = 0; i < polls; i++) {
            recorder.polled(poll(i, List.of(), List.of()));
        }
        out.release.countDown();
        recorder.close();
        String text = out.text.toString();
        long written = text.lines().filter(line -> line.contains(" poll ")).count();
        long dropped = text.lines().filter(line -> line.contains(" dropped ")).mapToLong(line -> Long.parseLong(line.split(" ")[2])).sum();
        assertTrue(written <= Recorder.MAX_QUEUED_POLLS + 1, written + " polls written");
        assertEquals(polls, written + dropped);
    }

    @Test
    void aDiskThatFailsIsSaidOnceAndTheRunGoesOn() throws Exception {
        Writer broken = new Writer() {
            @Override
            public void write(char[] text, int offset, int length) throws IOException {
                throw new IOException("No space left on device");
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() throws IOException {
                throw new IOException("No space left on device");
            }
        };
        Recorder recorder = new Recorder(dir.resolve("full.rec"), broken, now::get, 8);
        for (int i = 0; i < 100; i++) {
            recorder.robotRegistered("r" + i, "127.0.0.1", List.of());
            Thread.sleep(i % 10 == 0 ? 30 : 0);
        }
        recorder.close();
        assertEquals(List.of("WARNING the recording " + dir.resolve("full.rec") + " cannot be written any more: No space left on device"),
                logged);
    }
}
