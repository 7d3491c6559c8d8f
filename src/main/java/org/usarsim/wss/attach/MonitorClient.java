package org.usarsim.wss.attach;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicReference;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.JsonNode;

/**
 * A window's attachment to a WSS's monitor endpoint (docs/monitor.md): {@link #connect} reads the
 * state once (GET /api/state), then a thread of its own reads the event stream from after it
 * (GET /api/events with {@code Last-Event-ID}), keeps the {@link ServerState} and hands a new
 * {@link ServerView} over whenever what it read so far is applied (a batch: everything the stream
 * had buffered, or 100 ms of it). When the stream ends or fails it connects again after a growing
 * pause ({@link ReconnectPause}), resuming from the last event id it read. The event thread only
 * takes what is ready ({@link #takeView}, {@link #drainLog}, {@link #status}); force and replay
 * commands go out on a thread of their own.
 */
public final class MonitorClient implements AutoCloseable {

    private static final Logger LOG = Logger.getLogger(MonitorClient.class.getName());
    /** At most this many of the server's log lines wait for the window; past it the oldest are dropped. */
    static final int MAX_LOG = 5000;
    private static final long BATCH_MS = 100;

    /** One of the server's log lines: its level and message (escaped by the server). */
    public record LogLine(Level level, String message) {
    }

    private final MonitorHttp http;
    private final ServerState state = new ServerState();
    private final EventStreamParser parser = new EventStreamParser();
    private final ReconnectPause pause = new ReconnectPause();
    private final AtomicReference<ServerView> ready = new AtomicReference<>();
    private final ArrayDeque<LogLine> log = new ArrayDeque<>();
    private final RemoteReplay replay;
    private final ExecutorService commands = Executors.newSingleThreadExecutor(task -> daemon(task, "wss-attach-commands"));
    private final boolean operator;
    private Thread reader;
    private volatile boolean closed;
    private volatile InputStream stream;
    /** When the connection was lost and when the next try is (ms, System.currentTimeMillis()), or null while connected. */
    private volatile Lost lost;
    private Runnable changed = () -> { };

    private record Lost(long retryAtMs, String why) {
    }

    private MonitorClient(MonitorHttp http, JsonNode first) throws JsonException {
        this.http = http;
        state.replace(first);
        operator = first.get("operator").bool();
        JsonNode lastId = first.optional("lastEventId");
        if (lastId != null && !lastId.isNull()) {
            parser.line("id: " + lastId.string());
        }
        replay = new RemoteReplay(this::command);
        replay.follow(state.replay());
        ready.set(state.view());
    }

    /**
     * Reads the server's state at {@code base} with {@code token} (over https trusting only
     * {@code trustCert} when not null): an IOException saying why when it cannot (a refused token,
     * no server there, a certificate not trusted). Blocking: never on the event thread.
     */
    public static MonitorClient connect(URI base, String token, Path trustCert) throws IOException, InterruptedException {
        MonitorHttp http = new MonitorHttp(base, token, trustCert);
        JsonNode first = http.state();
        try {
            return new MonitorClient(http, first);
        } catch (JsonException e) {
            throw new IOException("the state the server at " + http.server() + " sent is not what docs/monitor.md says: " + e.getMessage());
        }
    }

    /** Starts reading the event stream; {@code onChange} runs on the client's thread when a view is ready. */
    public void start(Runnable onChange) {
        changed = onChange;
        reader = daemon(this::run, "wss-attach " + http.server());
        reader.start();
    }

    /** {@code host:port}. */
    public String server() {
        return http.server();
    }

    /** Whether the token is an operator's (the force menu and the rate dialog are offered). */
    public boolean operator() {
        return operator;
    }

    /** The newest view since the last call, else null. Any thread. */
    public ServerView takeView() {
        return ready.getAndSet(null);
    }

    /** The server's log lines since the last call, oldest first. */
    public List<LogLine> drainLog() {
        synchronized (log) {
            List<LogLine> lines = new ArrayList<>(log);
            log.clear();
            return lines;
        }
    }

    /** The time bar's controls while the server's model replays, else null. */
    public org.usarsim.wss.model.Replay replay() {
        return replay.running() ? replay : null;
    }

    /**
     * Null while connected; else the banner's words: "Connection to host:port lost, reconnecting in
     * N s", with why when the server said it (a refused token).
     */
    public String status(long nowMs) {
        Lost now = lost;
        if (now == null) {
            return null;
        }
        long seconds = Math.max(0, (now.retryAtMs() - nowMs + 999) / 1000);
        return "Connection to " + server() + " lost" + (now.why() == null ? "" : " (" + now.why() + ")") + ", reconnecting in "
                + seconds + " s";
    }

    /** POSTs the segments to the path: the control port's reply; an IOException with its error. Blocking. */
    public String post(String path, String segments) throws IOException, InterruptedException {
        return http.post(path, segments);
    }

    private void command(String path, String segments) {
        commands.execute(() -> {
            try {
                post(path, segments);
            } catch (IOException e) {
                LOG.warning(path + " " + segments + " failed: " + e.getMessage());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
    }

    private void run() {
        while (!closed) {
            String why = null;
            try {
                read(http.events(parser.lastEventId()));
            } catch (IOException e) {
                why = e.getMessage() != null && e.getMessage().startsWith("the server at") ? e.getMessage() : null;
            } catch (InterruptedException e) {
                return;
            } catch (JsonException e) {
                LOG.warning("the server at " + server() + " sent an event docs/monitor.md does not describe: " + e.getMessage()
                        + "; reading from a new snapshot");
                parser.forgetId(); // the next stream begins with a snapshot
            }
            if (closed) {
                return;
            }
            parser.reset();
            long now = System.currentTimeMillis();
            lost = new Lost(pause.lost(now), why);
            changed.run();
            try {
                pauseUntil(lost.retryAtMs());
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    /** Waits until the time, waking every half second so that the banner counts down. */
    private void pauseUntil(long atMs) throws InterruptedException {
        for (long left = atMs - System.currentTimeMillis(); left > 0 && !closed; left = atMs - System.currentTimeMillis()) {
            Thread.sleep(Math.min(left, 500));
            changed.run();
        }
    }

    private void read(InputStream body) throws IOException, JsonException {
        stream = body;
        try (BufferedReader in = new BufferedReader(new InputStreamReader(body, StandardCharsets.UTF_8))) {
            pause.connected();
            lost = null;
            boolean applied = false;
            long batchStart = System.currentTimeMillis();
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                EventStreamParser.Event event = parser.line(line);
                if (event != null) {
                    applied |= apply(event);
                }
                long now = System.currentTimeMillis();
                if (applied && (!in.ready() || now - batchStart >= BATCH_MS)) {
                    publish();
                    applied = false;
                    batchStart = now;
                }
            }
        } finally {
            stream = null;
        }
    }

    /** Applies one event; true when the state (or the log) changed. */
    private boolean apply(EventStreamParser.Event event) throws JsonException {
        JsonNode data = JsonNode.parse(event.data(), JsonLimits.DEFAULT);
        switch (event.type()) {
            case "snapshot" -> state.replace(data);
            case "log" -> logged(data);
            default -> {
                if (!state.apply(event.type(), data)) {
                    return false; // a type this client does not know: ignored
                }
            }
        }
        replay.follow(state.replay());
        return true;
    }

    private void logged(JsonNode data) throws JsonException {
        Level level;
        try {
            level = Level.parse(data.get("level").string());
        } catch (IllegalArgumentException e) {
            level = Level.INFO;
        }
        LogLine line = new LogLine(level, data.get("message").string());
        synchronized (log) {
            if (log.size() == MAX_LOG) {
                log.removeFirst();
            }
            log.addLast(line);
        }
    }

    private void publish() {
        ready.set(state.view());
        changed.run();
    }

    /** Stops reading and sending; the window closes. */
    @Override
    public void close() {
        closed = true;
        commands.shutdownNow();
        InputStream open = stream;
        if (reader != null) {
            reader.interrupt();
        }
        if (open != null) {
            try {
                open.close();
            } catch (IOException e) {
                // closing anyway
            }
        }
    }

    private static Thread daemon(Runnable task, String name) {
        Thread thread = new Thread(task, name);
        thread.setDaemon(true);
        return thread;
    }
}
