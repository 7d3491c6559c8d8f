package org.usarsim.wss.recording;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.time.temporal.ChronoUnit;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.LongSupplier;
import java.util.logging.Logger;
import java.util.zip.GZIPOutputStream;
import org.usarsim.wss.QueuedWriter;
import org.usarsim.wss.Version;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.model.WssEventListener;

/**
 * Records a run to a file (docs/replay.md, "Recording"): the header, then every poll of a
 * simulator model (its kicks, its walls when they changed, its robots and pairs), breaks, resumes,
 * forces, releases, rates, robots registering and leaving, each with its time in milliseconds
 * from the recorder's start, taken from its clock when the event is offered, and {@code end} at
 * {@link #close}. Not the data the links carry nor their ports: an entry per chunk would cost the
 * links what recording must never cost them.
 * <p>
 * As {@code hub.CsvEventLog} does it: the threads that fire events only put a small record in a
 * bounded queue and never wait; when it is full the event is counted, and {@code dropped N} is
 * written after the next batch. One writer thread ({@code wss-recorder}) writes in order and
 * flushes whenever it has caught up (a gzip file with a sync flush), so a run that crashes leaves
 * a file readable up to its last whole line. A disk that fails is said once; nothing more is written.
 */
public final class Recorder implements WssEventListener, AutoCloseable {

    private static final Logger LOG = Logger.getLogger(Recorder.class.getName());
    /** The time in the name of a recording the window starts: as the event log's. */
    private static final DateTimeFormatter RUN_TIME = DateTimeFormatter.ofPattern("yyyy.MM.dd-HH.mm.ss.SSS");
    /** What a file name that exists gets before its extension: the start's local time. */
    private static final DateTimeFormatter NAME_TIME = DateTimeFormatter.ofPattern("yyyy.MM.dd-HH.mm.ss");
    /** Events the writer may be behind by: breaks of many pairs at once come together. */
    static final int QUEUE_CAPACITY = 65_536;
    /**
     * Polls the writer may be behind by, within the queue: a poll of 100 robots holds 4,950 pairs,
     * so a disk that hangs must not let a whole queue of them fill the memory (about 50 s at 5 polls a second).
     */
    static final int MAX_QUEUED_POLLS = 256;
    /** One queued event: an entry, or a poll (written as its kicks, its walls if new, and itself), at its time. */
    private record Item(long millis, Entry entry, ModelPoll poll) {
    }

    private final Path file;
    /** The file asked for: {@link #file} unless that one existed. */
    private final Path asked;
    private final LongSupplier nanos;
    private final long startNanos;
    private final AtomicInteger queuedPolls = new AtomicInteger();
    private final QueuedWriter<Item> writer;
    /** The writer's: the walls last written (none before the first). */
    private List<Wall> writtenWalls = List.of();

    /**
     * A recorder writing to {@code out} (named {@code file}), whose header is already written,
     * behind a queue of {@code capacity} events, its times from {@code nanos} (nanoseconds) from now on.
     */
    Recorder(Path file, Writer out, LongSupplier nanos, int capacity) {
        this(file, file, out, nanos, capacity);
    }

    /** As above, {@code file} written where {@code asked} existed. */
    private Recorder(Path file, Path asked, Writer out, LongSupplier nanos, int capacity) {
        this.file = file;
        this.asked = asked;
        this.nanos = nanos;
        this.startNanos = nanos.getAsLong();
        this.writer = new QueuedWriter<>("wss-recorder", LOG, "the recording " + file, out, capacity, new QueuedWriter.Format<>() {
            @Override
            public void append(StringBuilder text, Item item) {
                format(text, item);
            }

            @Override
            public void dropped(StringBuilder text, long count) {
                EntryLines.write(text, new Entry.Dropped(millis(), count));
            }

            @Override
            public void end(StringBuilder text) {
                EntryLines.write(text, new Entry.End(millis()));
            }
        });
    }

    /**
     * Starts recording to {@code asked} (its folder created if missing; an existing file is kept and
     * the start time put in the new one's name, {@link #freeName}), gzip when its name ends in
     * {@code .gz}, with the header written: this WSS's version, the start, the model and the settings.
     * Says nothing yet: {@link #started} says where once the run has started, {@link #discard} removes
     * the file of a run that did not start.
     *
     * @throws IOException when the file cannot be created or written
     */
    public static Recorder create(Path asked, String model, Map<String, String> settings) throws IOException {
        return create(asked, model, settings, Instant.now(), System::nanoTime, QUEUE_CAPACITY);
    }

    static Recorder create(Path asked, String model, Map<String, String> settings, Instant started, LongSupplier nanos,
            int capacity) throws IOException {
        Path parent = asked.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        Path file = asked;
        OutputStream raw = null;
        for (int attempt = 0; raw == null; attempt++) {
            file = attempt == 0 ? asked : freeName(asked, started, attempt);
            try {
                raw = Files.newOutputStream(file, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
            } catch (FileAlreadyExistsException e) {
                if (attempt >= 100) {
                    throw e;
                }
            }
        }
        Writer out;
        try {
            OutputStream stream = file.getFileName().toString().endsWith(".gz") ? new GZIPOutputStream(raw, 1 << 16, true) : raw;
            out = new BufferedWriter(new OutputStreamWriter(stream, StandardCharsets.UTF_8), 1 << 16);
            StringBuilder header = new StringBuilder(1024);
            EntryLines.header(header, new Header(EntryLines.VERSION, Version.current(),
                    DateTimeFormatter.ISO_INSTANT.format(started.truncatedTo(ChronoUnit.MILLIS)), model, settings));
            out.append(header);
            out.flush();
        } catch (IOException | RuntimeException e) {
            raw.close();
            Files.deleteIfExists(file); // created here, and not a recording
            throw e;
        }
        return new Recorder(file, asked, out, nanos, capacity);
    }

    /** The run started: the log says where it is recorded (and when the file asked for existed, that it is kept). */
    public void started() {
        LOG.info("recording the run to " + file.toAbsolutePath()
                + (file.equals(asked) ? "" : " (" + asked.getFileName() + " exists: it is kept)"));
    }

    /**
     * The run did not start: closes the recording as {@link #close} does and deletes its file, which
     * recorded no run (docs/replay.md, "The file"). A file that cannot be deleted is said.
     */
    public void discard() {
        writer.close();
        try {
            Files.deleteIfExists(file);
        } catch (IOException e) {
            LOG.warning("the recording " + file + " of a run that did not start cannot be deleted: " + e);
        }
    }

    /**
     * The name a recording gets when {@code asked} exists: the start's local time inserted before
     * the extension ({@code run.rec} is {@code run-2026.11.25-14.30.00.rec}, {@code run.rec.gz}
     * {@code run-2026.11.25-14.30.00.rec.gz}, {@code run} {@code run-2026.11.25-14.30.00}); from the
     * second {@code attempt} on, {@code -2}, {@code -3}... after the time.
     */
    static Path freeName(Path asked, Instant started, int attempt) {
        String name = asked.getFileName().toString();
        String rest = name.endsWith(".gz") ? name.substring(0, name.length() - 3) : name;
        int dot = rest.lastIndexOf('.');
        int split = dot > 0 ? dot : rest.length();
        String time = NAME_TIME.format(started.atZone(ZoneId.systemDefault())) + (attempt > 1 ? "-" + attempt : "");
        return asked.resolveSibling(name.substring(0, split) + "-" + time + name.substring(split));
    }

    /** A new recording's file in {@code folder}, named by the time now: {@code run-yyyy.MM.dd-HH.mm.ss.SSS.rec} (the window's Record). */
    public static Path runFileIn(Path folder) {
        // Normalized: the log says /some/dir/run-....rec, not /some/dir/./run-....rec.
        return folder.resolve("run-" + RUN_TIME.format(LocalDateTime.now()) + ".rec").normalize();
    }

    /** The file being written (not the one asked for when that one existed). */
    public Path file() {
        return file;
    }

    private long millis() {
        return (nanos.getAsLong() - startNanos) / 1_000_000L;
    }

    /** Any thread: queues the entry or poll, or counts it as dropped when the writer is too far behind. Never waits. */
    private void offer(Entry entry, ModelPoll poll) {
        if (!writer.open()) {
            return;
        }
        if (poll != null && queuedPolls.incrementAndGet() > MAX_QUEUED_POLLS) {
            queuedPolls.decrementAndGet();
            writer.drop();
            return;
        }
        if (!writer.offer(new Item(entry != null ? entry.millis() : millis(), entry, poll)) && poll != null) {
            queuedPolls.decrementAndGet();
        }
    }

    private void offer(Entry entry) {
        offer(entry, null);
    }

    /** An item's lines: a poll as its kicks, its walls when they are not those last written, then the poll itself. */
    private void format(StringBuilder text, Item item) {
        ModelPoll poll = item.poll();
        if (poll == null) {
            EntryLines.write(text, item.entry());
            return;
        }
        queuedPolls.decrementAndGet();
        long t = item.millis();
        for (ModelPoll.Kick kick : poll.kicks()) {
            EntryLines.write(text, new Entry.Kick(t, kick.robot(), kick.batteryEmpty()));
        }
        if (!poll.walls().equals(writtenWalls)) {
            writtenWalls = poll.walls();
            EntryLines.write(text, new Entry.Walls(t, writtenWalls));
        }
        EntryLines.write(text, new Entry.Poll(t, poll.robots(), poll.pairs()));
    }

    @Override
    public void robotRegistered(String robot, String address, List<Integer> ports) {
        offer(new Entry.Registered(millis(), robot, address));
    }

    @Override
    public void robotDeregistered(String robot) {
        offer(new Entry.Left(millis(), robot));
    }

    @Override
    public void connectionOutOfRange(String from, String to, double strength, double distance) {
        offer(new Entry.Break(millis(), from, to, strength, distance));
    }

    @Override
    public void connectionInRange(String from, String to) {
        offer(new Entry.Resume(millis(), from, to));
    }

    @Override
    public void pairForced(String first, String second, boolean up) {
        offer(new Entry.Force(millis(), first, second, up));
    }

    @Override
    public void pairPinned(String first, String second, long bitsPerSecond, int delayMs, int jitterMs) {
        offer(new Entry.Pin(millis(), first, second, bitsPerSecond, delayMs, jitterMs));
    }

    @Override
    public void pairReleased(String first, String second) {
        offer(new Entry.Release(millis(), first, second));
    }

    @Override
    public void replayMoved(double timeSeconds, double speed, boolean playing) {
        offer(new Entry.Replay(millis(), timeSeconds, speed, playing));
    }

    @Override
    public void rateChanged(String from, String to, long bitsPerSecond) {
        offer(new Entry.Rate(millis(), from, to, bitsPerSecond));
    }

    @Override
    public void udpCounted(String from, String to, int fixedPort, long datagrams, long bytes, long droppedBroken, long droppedQueue,
            long lost) {
        offer(new Entry.Udp(millis(), from, to, fixedPort, datagrams, bytes, droppedBroken, droppedQueue, lost));
    }

    /** A poll: its kicks, its walls when they changed and the poll itself, at the time it is offered. */
    @Override
    public void polled(ModelPoll poll) {
        offer(null, poll);
    }

    /**
     * Stops taking events, waits (at most 10 s, for a disk that hangs) until the writer has written
     * everything queued before, the count of any dropped, {@code end}, and closed the file (a gzip
     * file whole).
     */
    @Override
    public void close() {
        writer.close();
    }
}
