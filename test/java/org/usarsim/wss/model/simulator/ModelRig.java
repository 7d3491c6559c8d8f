package org.usarsim.wss.model.simulator;

import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.WssEventListener;

/**
 * A simulator model under test, for real: a {@link FakeSimulator} (or another simulator), the
 * model polling it every 100 ms (unless the settings say otherwise), a hub on 127.0.0.1, the hub's
 * events and the model's log lines as they happen. With a {@link ManualClock} (the model made with
 * it), the model polls only when the test says: {@link #polls} wakes it, and events carry the
 * clock's time.
 */
public final class ModelRig implements AutoCloseable {

    /** One event as it happened: its words (type, then arguments) and when. */
    public record Event(String type, List<Object> args, long nanos) {
        @Override
        public String toString() {
            return type + args;
        }
    }

    /** How a test makes a rig once it knows the simulator's port. */
    @FunctionalInterface
    public interface Factory {
        ModelRig create(int simulatorPort) throws Exception;
    }

    public final FakeSimulator sim;
    public final SimulatorModel model;
    public final TestHub server;
    /** The model's clock when the test moves it; null on the machine's clock. */
    public final ManualClock clock;
    public final List<Event> events = new CopyOnWriteArrayList<>();
    public final List<LogRecord> log;
    private final List<AutoCloseable> toClose = new ArrayList<>();
    private final Map<String, ServerSocket> accepting = new java.util.concurrent.ConcurrentHashMap<>();
    private final LogCapture capture;

    /** The model polling a new {@link FakeSimulator}. */
    public ModelRig(SimulatorModel model, Map<String, String> settings) throws Exception {
        this(model, settings, new FakeSimulator(), 0, null);
    }

    /** The model, made with {@code clock}, polling a new {@link FakeSimulator} when {@link #polls} says. */
    public ModelRig(SimulatorModel model, Map<String, String> settings, ManualClock clock) throws Exception {
        this(model, settings, new FakeSimulator(), 0, clock);
    }

    /** The model polling this fake, set up by the caller before the model's first poll. */
    public static ModelRig with(FakeSimulator fake, SimulatorModel model, Map<String, String> settings) throws Exception {
        return new ModelRig(model, settings, fake, 0, null);
    }

    /** The model polling a simulator that already runs on 127.0.0.1 at {@code port} (no fake: {@link #sim} is null). */
    public static ModelRig polling(int port, SimulatorModel model, Map<String, String> settings) throws Exception {
        return new ModelRig(model, settings, null, port, null);
    }

    private ModelRig(SimulatorModel model, Map<String, String> settings, FakeSimulator fake, int port, ManualClock clock)
            throws Exception {
        this.model = model;
        this.clock = clock;
        sim = fake;
        Map<String, String> all = new LinkedHashMap<>();
        all.put("usarsim.host", "127.0.0.1");
        all.put("usarsim.port", Integer.toString(fake != null ? fake.port() : port));
        all.put("usarsim.interval", "100");
        all.put("usarsim.timeout", "300");
        all.putAll(settings);
        model.configure(new ModelSettings(all));
        capture = LogCapture.of(model.getClass().getName(), Level.FINE);
        log = capture.records;
        server = new TestHub(model, true, 65536);
        server.hub.addListener(new WssEventListener() {
            @Override
            public void robotDeregistered(String robot) {
                add("DEREGISTERED", robot);
            }

            @Override
            public void robotOutOfBattery(String robot) {
                add("OUT_OF_BATTERY", robot);
            }

            @Override
            public void connectionOutOfRange(String from, String to, double strength, double distance) {
                add("OUT_OF_RANGE", from, to, strength, distance);
            }

            @Override
            public void connectionInRange(String from, String to) {
                add("IN_RANGE", from, to);
            }
        });
    }

    private void add(String type, Object... args) {
        events.add(new Event(type, List.of(args), clock != null ? clock.nanoTime() : System.nanoTime()));
    }

    /** The events of these types, in order. */
    public List<Event> events(String... types) {
        List<String> wanted = List.of(types);
        return events.stream().filter(e -> wanted.contains(e.type())).toList();
    }

    /** The model's log lines at this level whose text contains {@code part}. */
    public long logLines(Level level, String part) {
        return capture.count(level, part);
    }

    /** Places the robot in the fake simulator and registers it, accepting connections on one port. */
    public TestRobot robot(String name, double x, double y, double z) throws Exception {
        sim.place(name, x, y, z);
        return robot(name);
    }

    /** Registers a robot, accepting connections on one port. */
    public TestRobot robot(String name) throws Exception {
        TestRobot robot = server.robot();
        toClose.add(robot);
        accepting.put(name, robot.initAccepting(name));
        return robot;
    }

    /** The socket on which the robot registered by {@link #robot} accepts connections. */
    public ServerSocket accepts(String name) {
        return accepting.get(name);
    }

    /** Waits until the model has completed {@code count} more polls; on a {@link ManualClock}, makes them happen. */
    public void polls(int count) {
        if (clock != null) {
            for (int i = 0; i < count; i++) {
                clock.wakePoller();
            }
            return;
        }
        long target = sim.getposCount() + count + 1;
        Wait.until(count + " polls of the simulator", () -> sim.getposCount() >= target);
    }

    @Override
    public void close() throws Exception {
        for (AutoCloseable closeable : toClose) {
            closeable.close();
        }
        server.close();
        if (sim != null) {
            sim.close();
        }
        capture.close();
    }
}
