package org.usarsim.wss.hub;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.logging.Logger;
import java.util.stream.Collectors;
import org.usarsim.wss.LogText;
import org.usarsim.wss.QueuedWriter;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.protocol.Strengths;

/**
 * The original's "Enable Logging" file: one CSV line per event in
 * {@code log-yyyy.MM.dd-HH.mm.ss.SSS.txt}, with the time of day as {@code HH:mm:ss.SSS}.
 * <p>
 * The threads that fire events (link threads, once per chunk) only put a small record, stamped
 * with the time of the event (the hub's clock), in a bounded queue and never wait: when the queue is full the event
 * is counted as dropped. One writer thread ({@code wss-event-log}) takes what is queued, writes it
 * in order and flushes whenever it has caught up, so the file is current while the log is open;
 * once caught up, it lets the next events gather for 20 ms before it writes again.
 * After a batch in which events were dropped it writes {@code DROPPED,t,n} (n events not written
 * since the previous such line; docs/headless.md). {@link #close} writes everything queued first.
 * A field that needs it (a name with a comma, a quote or a LF) is quoted as RFC 4180 says, its
 * control and format characters escaped as in the log ({@code \u001B}) and its backslashes doubled.
 * The queue and its thread are {@link QueuedWriter}'s, as the recording's.
 */
public final class CsvEventLog implements WssEventListener, AutoCloseable {

    private static final Logger LOG = Logger.getLogger(CsvEventLog.class.getName());
    private static final DateTimeFormatter FILE_TIME = DateTimeFormatter.ofPattern("yyyy.MM.dd-HH.mm.ss.SSS");
    /** Events the writer may be behind by: a few seconds of chunks of one fast link. */
    static final int QUEUE_CAPACITY = 65_536;

    /** One event as it will be written: its type, when it happened, its fields. */
    private record Line(String type, long millis, Object... fields) {
    }

    /**
     * A DATA_SENT, the one event a link fires per chunk: its own record, so that the link's
     * thread makes one small object and no array and no boxed count (docs/performance.md).
     */
    private record DataSent(String from, String to, int bytes, long millis) {
    }

    private final Path file;
    /** The hub's clock: each line's time. */
    private final HubClock clock;
    /** Queues {@link Line}s and {@link DataSent}s. */
    private final QueuedWriter<Object> writer;
    /** The writer's: a line's time of day. */
    private final LineTime lineTime = new LineTime(ZoneId.systemDefault());

    /** The log writing to {@code out} (named {@code file}), behind a queue of {@code capacity} events, its times from {@code clock}. */
    CsvEventLog(Path file, Writer out, int capacity, HubClock clock) {
        this.file = file;
        this.clock = clock;
        this.writer = new QueuedWriter<>("wss-event-log", LOG, "the event log " + file, out, capacity, new QueuedWriter.Format<>() {
            @Override
            public void append(StringBuilder text, Object item) {
                if (item instanceof DataSent sent) {
                    format(text, sent);
                } else {
                    Line line = (Line) item;
                    format(text, line.type, line.millis, line.fields);
                }
            }

            @Override
            public void dropped(StringBuilder text, long count) {
                format(text, "DROPPED", clock.wallMillis(), count);
            }
        });
    }

    /** As {@link #create(Path, HubClock)}, on the machine's clock. */
    public static CsvEventLog create(Path directory) throws IOException {
        return create(directory, HubClock.SYSTEM);
    }

    /** Creates a new log file in the directory (created if missing), named by the time now; its times are the hub's {@code clock}'s. */
    public static CsvEventLog create(Path directory, HubClock clock) throws IOException {
        Files.createDirectories(directory);
        LocalDateTime now = LocalDateTime.ofInstant(Instant.ofEpochMilli(clock.wallMillis()), ZoneId.systemDefault());
        Path file = directory.resolve("log-" + FILE_TIME.format(now) + ".txt");
        BufferedWriter out = Files.newBufferedWriter(file, StandardCharsets.UTF_8);
        LOG.info("writing the event log to " + file.toAbsolutePath());
        return new CsvEventLog(file, out, QUEUE_CAPACITY, clock);
    }

    public Path file() {
        return file;
    }

    /** Any thread: queues the event, or counts it as dropped when the writer is too far behind. Never waits. */
    private void event(String type, Object... fields) {
        if (writer.open()) {
            writer.offer(new Line(type, clock.wallMillis(), fields));
        }
    }

    private void format(StringBuilder text, String type, long millis, Object... fields) {
        text.append(type).append(',');
        lineTime.append(text, millis);
        for (Object field : fields) {
            text.append(',');
            appendField(text, String.valueOf(field));
        }
        text.append(System.lineSeparator());
    }

    /** As {@link #format(StringBuilder, String, long, Object...)} would write it with its three fields. */
    private void format(StringBuilder text, DataSent sent) {
        text.append("DATA_SENT,");
        lineTime.append(text, sent.millis);
        text.append(',');
        appendField(text, sent.from);
        text.append(',');
        appendField(text, sent.to);
        text.append(',').append(sent.bytes).append(System.lineSeparator());
    }


    /**
     * A field as RFC 4180 writes it: as it is, unless it holds a comma, a double quote, a CR or a
     * LF (a robot name may: {@code INIT {Robot a,b}}); then between double quotes, each double quote
     * in it doubled. A name never breaks the line into more fields or more lines. Before that, the
     * characters a terminal or a viewer would obey (ESC, the bidirectional overrides...) are
     * escaped as the log escapes them ({@link LogText}), so that {@code cat} of the file shows them,
     * after each backslash of the name itself is doubled: {@code \\} is a backslash, {@code \}{@code uXXXX}
     * one escaped character, so a name {@code a<ESC>b} ({@code a\}{@code u001Bb}) and a name
     * {@code a\}{@code u001Bb} ({@code a\\u001Bb}) are never written alike (issue 36).
     */
    static void appendField(StringBuilder text, String raw) {
        String field = LogText.escape(raw.indexOf('\\') < 0 ? raw : raw.replace("\\", "\\\\"));
        boolean quote = false;
        for (int i = 0; i < field.length() && !quote; i++) {
            char c = field.charAt(i);
            quote = c == ',' || c == '"' || c == '\r' || c == '\n';
        }
        if (!quote) {
            text.append(field);
            return;
        }
        text.append('"');
        for (int i = 0; i < field.length(); i++) {
            char c = field.charAt(i);
            text.append(c);
            if (c == '"') {
                text.append('"');
            }
        }
        text.append('"');
    }

    @Override
    public void robotRegistered(String robot, String address, List<Integer> ports) {
        event("REGISTERED", robot, address, ports.stream().map(String::valueOf).collect(Collectors.joining(":")));
    }

    @Override
    public void robotDeregistered(String robot) {
        event("DEREGISTERED", robot);
    }

    @Override
    public void robotOutOfBattery(String robot) {
        event("OUT_OF_BATTERY", robot);
    }

    @Override
    public void connectionOutOfRange(String from, String to, double strength, double distance) {
        event("OUT_OF_RANGE", from, to, Strengths.format(strength), Strengths.format(distance));
    }

    @Override
    public void connectionInRange(String from, String to) {
        event("IN_RANGE", from, to);
    }

    @Override
    public void connectionEstablished(String from, String to, int targetPort) {
        event("CON_ESTABLISHED", from, to, targetPort);
    }

    @Override
    public void connectionTerminated(String from, String to, int targetPort) {
        event("CON_TERMINATED", from, to, targetPort);
    }

    @Override
    public void dataSent(String from, String to, int bytes) {
        writer.offer(new DataSent(from, to, bytes, clock.wallMillis()));
    }

    @Override
    public void udpCounted(String from, String to, int fixedPort, long datagrams, long bytes, long droppedBroken, long droppedQueue,
            long lost) {
        event("UDP", from, to, fixedPort, datagrams, bytes, droppedBroken, droppedQueue, lost);
    }

    @Override
    public void pairForced(String first, String second, boolean up) {
        event("FORCED", first, second, up ? "UP" : "DOWN");
    }

    /** {@code PINNED,t,A,B,RATE,DELAY,JITTER}: bit/s and ms, a field not pinned empty. */
    @Override
    public void pairPinned(String first, String second, long bitsPerSecond, int delayMs, int jitterMs) {
        event("PINNED", first, second, bitsPerSecond > 0 ? Long.toString(bitsPerSecond) : "", delayMs >= 0 ? Integer.toString(delayMs) : "",
                jitterMs >= 0 ? Integer.toString(jitterMs) : "");
    }

    @Override
    public void pairReleased(String first, String second) {
        event("RELEASED", first, second);
    }

    /** An operator moved the replay: where it is now (s, to the millisecond), its speed, PLAY or PAUSE. Never limited, as the log's lines are. */
    /** A setting the run's random draws depend on (shadowing.*, wss.seed), written at the start: {@code SETTING,t,key,value}. */
    public void setting(String key, String value) {
        event("SETTING", key, value);
    }

    @Override
    public void replayMoved(double timeSeconds, double speed, boolean playing) {
        event("REPLAY", Strengths.format(Math.round(timeSeconds * 1000) / 1000.0), Strengths.format(speed), playing ? "PLAY" : "PAUSE");
    }

    /** With links shaped: a pair's rate one way was set or changed (never per chunk). */
    @Override
    public void rateChanged(String from, String to, long bitsPerSecond) {
        event("RATE", from, to, bitsPerSecond);
    }

    /** A robot is cut off from the base (docs/routes.md): {@code CUT_OFF,t,robot}. */
    @Override
    public void cutOff(String robot) {
        event("CUT_OFF", robot);
    }

    /** A robot has a route to the base, or another one: {@code ROUTE,t,robot,hops,rate} (the rate empty unshaped). */
    @Override
    public void routedToBase(String robot, int hops, String path, long bitsPerSecond) {
        event("ROUTE", robot, hops, bitsPerSecond > 0 ? Long.toString(bitsPerSecond) : "");
    }

    /**
     * Stops taking events, waits (at most 10 s, for a disk that hangs) until the writer has
     * written everything queued before, with the count of any dropped, and closed the file.
     */
    @Override
    public void close() {
        writer.close();
    }
}
