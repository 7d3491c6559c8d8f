package org.usarsim.wss.monitor;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.model.StateChangeListener;
import org.usarsim.wss.ros.Json;
import org.usarsim.wss.routes.RouteListener;
import org.usarsim.wss.routes.RouteTable;

/**
 * The monitor's one thread of events, {@code wss-monitor-events}: it takes the hub's state when the
 * {@link Cadence} says, tells the streams what changed ({@link StateDiff}), numbers every event in
 * the {@link EventHistory}, starts each new stream with what it missed or a snapshot, and passes on
 * the log records. It makes the routes' JSON once per route table ({@link RoutesJson}: every
 * robot's search, on this thread only), which the state, the stream and /metrics share.
 * The hub's threads only mark the state changed and offer to a bounded queue:
 * never a lock, never a wait (a full queue drops the item and counts it).
 */
final class Publisher implements StateChangeListener, RouteListener, Runnable {

    private static final Logger LOG = Logger.getLogger(Publisher.class.getName());
    static final int MAX_WAITING = 8192;
    private static final Object CHANGED = new Object();

    /** A stream to start: what it last got (null: nothing) and whether its token is an operator's. */
    private record Join(EventStream stream, String lastEventId, boolean operator) {
    }

    /** A log record, as the stream tells it. */
    record LogLine(Map<String, Object> json) {
    }

    private final Watched watched;
    /** What does not change during the run, set once the control port listens. */
    private volatile StateJson.Server server;
    private final Streams streams;
    private final EventHistory history;
    private final StateDiff diff = new StateDiff();
    /** The linger after the last stream: {@link Cadence#LINGER_NS}, or the benchmarks' -Dwss.monitor.lingerMs. */
    private final Cadence cadence = new Cadence(Long.getLong("wss.monitor.lingerMs", Cadence.LINGER_NS / 1_000_000) * 1_000_000);
    private final BlockingQueue<Object> waiting = new ArrayBlockingQueue<>(MAX_WAITING);
    private final AtomicBoolean changed = new AtomicBoolean();
    private final AtomicLong droppedItems = new AtomicLong();
    private final Set<String> outOfBattery = ConcurrentHashMap.newKeySet();
    /** The routes as last made from the hub's table (this thread makes them; requests read them). */
    private volatile RoutesJson routes = RoutesJson.EMPTY;
    private volatile boolean stopped;
    private boolean everStreamed;
    private boolean recording;
    private Thread thread;

    Publisher(Watched watched, StateJson.Server server, Streams streams, EventHistory history) {
        this.watched = watched;
        this.server = server;
        this.streams = streams;
        this.history = history;
    }

    void server(StateJson.Server about) {
        server = about;
    }

    void start() {
        thread = new Thread(this, "wss-monitor-events");
        thread.setDaemon(true);
        thread.start();
    }

    void stop() {
        stopped = true;
        if (thread != null) {
            thread.interrupt();
        }
    }

    /** Items the hub's threads, the log or a stream's start could not queue. */
    long dropped() {
        return droppedItems.get();
    }

    /** A new stream (its slot taken): started by the thread with what it missed or a snapshot; false when it could not be queued. */
    boolean join(EventStream stream, String lastEventId, boolean operator) {
        return offer(new Join(stream, lastEventId, operator));
    }

    /** A log record for the streams (any thread). */
    void log(Map<String, Object> json) {
        offer(new LogLine(json));
    }

    /** The state now, for GET /api/state (the caller's thread). */
    Map<String, Object> state(boolean operator) {
        return StateJson.state(read(), server, history.run(), SseEvent.id(history.run(), history.last()), Instant.now(), operator);
    }

    private boolean offer(Object item) {
        if (waiting.offer(item)) {
            return true;
        }
        droppedItems.incrementAndGet();
        return false;
    }

    private Reading read() {
        return Reading.of(watched.hub().snapshot(), watched.model(), watched.modelSettings(), outOfBattery, routes);
    }

    /** The routes as last made (for /metrics). */
    RoutesJson routes() {
        return routes;
    }

    /** This thread: the routes' JSON made again when the hub's table is another one. */
    private void refreshRoutes() {
        RouteTable now = watched.hub().routes();
        if (now != routes.table() && !now.equals(routes.table())) {
            routes = RoutesJson.of(now);
        }
    }

    @Override
    public void run() {
        while (!stopped) {
            try {
                long now = System.nanoTime();
                Object first = waiting.poll(cadence.waitNs(now, changed.get()), TimeUnit.NANOSECONDS);
                List<Object> items = new java.util.ArrayList<>();
                if (first != null) {
                    items.add(first);
                    waiting.drainTo(items); // all that waits, not one item per comparison
                }
                for (Object item : items) {
                    if (item instanceof Join join) {
                        start(join);
                    } else if (item instanceof LogLine line && recording) {
                        publish("log", line.json());
                    }
                }
                now = System.nanoTime();
                boolean open = !streams.isEmpty();
                if (open) {
                    cadence.streaming(now);
                }
                recording = cadence.recording(now, open, everStreamed);
                if (cadence.due(now, changed.get())) {
                    refreshRoutes();
                    boolean counts = cadence.compared(now);
                    boolean hub = changed.getAndSet(false);
                    if (recording && (hub || counts)) {
                        for (StateDiff.Change change : diff.step(read(), counts)) {
                            publish(change.type(), change.data());
                        }
                    }
                }
            } catch (InterruptedException e) {
                if (stopped) {
                    break;
                }
            } catch (RuntimeException e) {
                LOG.log(Level.WARNING, "monitor: reading the state failed: " + e, e);
            }
        }
        streams.closeAll();
    }

    private void publish(String type, Object data) {
        streams.publish(history.append(type, Json.write(data)));
    }

    /** Starts the stream with the events after its last one, or a snapshot of what the events so far told. */
    private void start(Join join) {
        if (!recording) {
            history.forget();
            diff.reset(read());
            recording = true;
        }
        everStreamed = true;
        cadence.streaming(System.nanoTime());
        List<SseEvent> missed = history.after(join.lastEventId());
        if (missed == null) {
            String last = SseEvent.id(history.run(), history.last());
            Map<String, Object> state = StateJson.state(diff.sent(), server, history.run(), last, Instant.now(), join.operator());
            join.stream().offer(SseEvent.of(history.run(), history.last(), "snapshot", Json.write(state)));
        } else {
            missed.forEach(join.stream()::offer);
        }
        streams.add(join.stream());
    }

    @Override
    public void changed() {
        if (!changed.getAndSet(true)) {
            offer(CHANGED); // wakes the thread; a full queue wakes it anyway
        }
    }

    @Override
    public void routesChanged(RouteTable table) {
        changed();
    }

    @Override
    public void robotRegistered(String robot, String address, List<Integer> ports) {
        outOfBattery.remove(robot);
        changed();
    }

    @Override
    public void robotOutOfBattery(String robot) {
        outOfBattery.add(robot);
        changed();
    }

}
