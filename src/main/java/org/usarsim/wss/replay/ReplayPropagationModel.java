package org.usarsim.wss.replay;

import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import java.util.logging.Level;
import org.usarsim.wss.Decimals;
import org.usarsim.wss.model.ModelInputException;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.model.simulator.PollStep;
import org.usarsim.wss.model.simulator.PollingModel;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingException;
import org.usarsim.wss.recording.RecordingReader;

/**
 * Replays a recording (docs/replay.md) with no simulator: its polls, one after the other at their
 * recorded times (or faster, slower, from elsewhere: {@link #replay()}), are applied as the
 * simulator models apply theirs. Robots register live, by name; at each poll the registered robots
 * the poll does not list, or lists with an empty battery, are kicked (a robot the recording never
 * had is kicked as the DistanceOnly model kicks one the simulator does not list, and may connect
 * until then); every pair of present robots gets its recorded link state, breaks and resumes in one
 * go. GETSS answers the recorded strength of the poll applied last, the map its recorded positions
 * and the walls recorded by then.
 *
 * <p>Its thread, {@code replay}, applies a poll when the replay's time reaches it (a jump, a change
 * of speed or play wakes it at once) and when the registered robots change, so that a robot that
 * registers while the replay holds still is decided too.
 */
public final class ReplayPropagationModel extends PollingModel {

    /** How long the replay's thread waits at most before it looks again. */
    private static final long TICK_NANOS = TimeUnit.MILLISECONDS.toNanos(20);

    static final List<Setting> SETTINGS = List.of(
            Setting.text("replay.file", "Recording", "").noun("the path of a recording").orEmpty("not set yet; Start refuses it")
                    .help("The recording to replay (wss.record writes one; .gz read as gzip), relative to the working directory"),
            Setting.number("replay.speed", "Speed", "1").from(Replay.MIN_SPEED).to(Replay.MAX_SPEED)
                    .help("How fast the replay runs: 1 is as recorded, 2 twice as fast, 0.25 a quarter"),
            Setting.number("replay.start", "Start at", "0").from(0).unit("s")
                    .help("Where the replay begins, in seconds from the recording's start"),
            Setting.bool("replay.loop", "Loop", false)
                    .help("At the end, start again from 0; otherwise the replay stops there and holds its last poll"));

    private final LongSupplier clock;
    private final Controls controls = new Controls();

    /** The replay of the current run, from a start to its shutdown; {@link Run#STOPPED} while stopped. */
    private volatile Run run = Run.STOPPED;
    /** The poll applied last, swapped whole: GETSS, DNS, accepts and the map read it. */
    private volatile Applied applied = Applied.NONE;
    /** The recording's cutoff (its distance.cutoff setting), NaN when it has none. */
    private volatile double cutoff = Double.NaN;

    /** A replay on the machine's clock. */
    public ReplayPropagationModel() {
        this(System::nanoTime);
    }

    /** A replay whose time comes from {@code clock} (nanoseconds, as {@link System#nanoTime()}); a test moves it. */
    ReplayPropagationModel(LongSupplier clock) {
        this.clock = clock;
    }

    /** The poll applied last: its index, its robots by name, its pairs. */
    private record Applied(int index, Map<String, ModelPoll.Robot> robots, Map<RobotPair, ModelPoll.Pair> pairs) {
        static final Applied NONE = new Applied(-1, Map.of(), Map.of());
    }

    /** replay.file, replay.speed, replay.start, replay.loop. */
    @Override
    public List<Setting> settings() {
        return SETTINGS;
    }

    /**
     * Reads the recording and starts replaying it.
     *
     * @throws ModelInputException when replay.file is empty, missing, not a recording, of another
     *                             version or without a poll, or replay.start is past its end
     */
    @Override
    public synchronized void start() throws ModelStartException {
        if (isActive()) {
            return;
        }
        RobotLinkModel server = server();
        ModelSettings values = checked();
        String file = values.getString("replay.file", "");
        if (file.isEmpty()) {
            throw new ModelInputException("replay.file is empty: name the recording to replay (docs/replay.md)");
        }
        Recording recording;
        try {
            recording = RecordingReader.read(Path.of(file));
        } catch (RecordingException e) {
            throw new ModelInputException(e.getMessage(), e);
        } catch (InvalidPathException e) {
            throw new ModelInputException("replay.file = '" + file + "' is not a path: " + e.getMessage(), e);
        }
        if (recording.polls().isEmpty()) {
            throw new ModelInputException(file + " holds no poll (recorded with " + recording.header().model()
                    + "): nothing to replay; a recording of a simulator model has one per poll interval");
        }
        long startMillis = Math.round(values.getDouble("replay.start", 0) * 1000);
        if (startMillis > recording.durationMillis()) {
            throw new ModelInputException("replay.start = " + values.getString("replay.start", "") + " s is past the end of "
                    + file + " (" + minutesSeconds(recording.durationMillis()) + ")");
        }
        double speed = values.getDouble("replay.speed", 1);
        boolean loop = values.getBoolean("replay.loop", false);
        cutoff = cutoffOf(recording);
        applied = Applied.NONE;
        tell(file, recording, startMillis, speed, loop);
        run = new Player(server, recording, new ReplayClock(recording.durationMillis(), loop, startMillis, speed, clock.getAsLong()));
    }

    /** The given values over the declared defaults, each by its rule. */
    private ModelSettings checked() throws ModelInputException {
        Map<String, String> stripped = new LinkedHashMap<>();
        given().forEach((key, value) -> stripped.put(key, value.strip()));
        try {
            return new ModelSettings(Setting.checked(SETTINGS, stripped));
        } catch (IllegalArgumentException e) {
            throw new ModelInputException(e.getMessage());
        }
    }

    /** The INFO line of what is replayed, and a WARNING for each thing the reader had to leave out. */
    private void tell(String file, Recording recording, long startMillis, double speed, boolean loop) {
        Set<String> robots = recording.robots();
        log.info("replaying " + file + ": recorded with " + recording.header().model() + ", "
                + minutesSeconds(recording.durationMillis()) + " long, " + recording.polls().size()
                + (recording.polls().size() == 1 ? " poll, " : " polls, ")
                + robots.size() + (robots.size() == 1 ? " robot " : " robots ") + robots + "; from "
                + minutesSeconds(startMillis) + " at " + Decimals.plain(speed) + "x" + (loop ? ", looping" : ""));
        if (recording.cutShort()) {
            log.warning(file + " was cut short (a run that did not stop): replaying up to its last whole line at "
                    + minutesSeconds(recording.durationMillis()));
        }
        int skipped = recording.unknownLines() + recording.unreadableLines();
        if (skipped > 0) {
            log.warning(file + ": skipped " + skipped + (skipped == 1 ? " line" : " lines") + " ("
                    + recording.unknownLines() + " with a keyword this WSS does not know, " + recording.unreadableLines()
                    + " that cannot be read); the first: " + recording.firstProblem());
        }
    }

    private static double cutoffOf(Recording recording) {
        String value = recording.header().settings().get("distance.cutoff");
        try {
            return value == null ? Double.NaN : Double.parseDouble(value);
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    /** Stops the replay's thread; the pairs stay as the last poll left them until the server closes them. */
    @Override
    public void shutdown() {
        Run stopping;
        synchronized (this) {
            stopping = run;
            run = Run.STOPPED;
        }
        stopping.stop();
    }

    @Override
    public boolean isActive() {
        return run != Run.STOPPED;
    }

    /** The recorded strength of the pair at the poll applied last (the same both ways); NaN when the poll has no such pair. */
    @Override
    public double getSignalStrengthForPair(String from, String to) {
        ModelPoll.Pair pair = applied.pairs().get(RobotPair.of(from, to));
        return pair == null ? Double.NaN : pair.strength();
    }

    /**
     * The pair's recorded link state at the poll applied last; true for a pair it has no state for
     * (a robot it does not list may connect until the next poll kicks it, as with DistanceOnly).
     */
    @Override
    public boolean connectionIsPossibleForPair(String from, String to) {
        ModelPoll.Pair pair = applied.pairs().get(RobotPair.of(from, to));
        return pair == null || pair.live();
    }

    /** Where the poll applied last recorded the robot. */
    @Override
    public Optional<Position> positionOf(String robot) {
        ModelPoll.Robot known = applied.robots().get(robot);
        return known == null ? Optional.empty() : Optional.of(known.position());
    }

    /** The walls recorded at or before the replay's time. */
    @Override
    public List<Wall> walls() {
        return run.walls();
    }

    /** The recorded run's cutoff (its distance.cutoff setting); NaN when it had none. */
    @Override
    public double cutoff() {
        return cutoff;
    }

    /** The replay's controls: play, pause, speed, jump. They act on the current run (nothing while stopped). */
    @Override
    public Optional<Replay> replay() {
        return Optional.of(controls);
    }

    /** mm:ss (minutes beyond 59 as they are), as the log says a time of the recording. */
    static String minutesSeconds(long millis) {
        long seconds = millis / 1000;
        return String.format(java.util.Locale.ROOT, "%02d:%02d", seconds / 60, seconds % 60);
    }

    /** The controls, for the window's time bar and the operator's {@code REPLAY} command: they act on the running replay. */
    private final class Controls implements Replay {

        @Override
        public double durationSeconds() {
            return run.durationSeconds();
        }

        @Override
        public double timeSeconds() {
            return run.timeSeconds();
        }

        @Override
        public double pollSeconds() {
            return run.pollSeconds();
        }

        @Override
        public double speed() {
            return run.speed();
        }

        @Override
        public boolean playing() {
            return run.playing();
        }

        @Override
        public void play() {
            run.play();
        }

        @Override
        public void pause() {
            run.pause();
        }

        @Override
        public void speed(double times) {
            if (!(times >= MIN_SPEED && times <= MAX_SPEED)) {
                throw new IllegalArgumentException("a speed of " + times + " is not from " + MIN_SPEED + " to " + MAX_SPEED);
            }
            run.speed(times);
        }

        @Override
        public void jump(double seconds) {
            Run running = run;
            double duration = running.durationSeconds();
            if (!(seconds >= 0 && seconds <= duration)) {
                throw new IllegalArgumentException(seconds + " s is not in the recording (0 to " + duration + " s)");
            }
            running.jump(seconds);
        }
    }

    /** A run of the replay as the controls and the map see it: the {@link Player} from a start to its shutdown, or none. */
    private interface Run extends Replay {

        /** No replay: nothing to play, its time 0, at speed 1; the controls do nothing. */
        Run STOPPED = new Run() {
            @Override
            public double durationSeconds() {
                return 0;
            }

            @Override
            public double pollSeconds() {
                return 0;
            }

            @Override
            public double timeSeconds() {
                return 0;
            }

            @Override
            public double speed() {
                return 1;
            }

            @Override
            public boolean playing() {
                return false;
            }

            @Override
            public void play() {
            }

            @Override
            public void pause() {
            }

            @Override
            public void speed(double times) {
            }

            @Override
            public void jump(double seconds) {
            }

            @Override
            public List<Wall> walls() {
                return List.of();
            }

            @Override
            public void stop() {
            }
        };

        /** The walls recorded at or before the replay's time. */
        List<Wall> walls();

        /** Stops the run's thread. */
        void stop();
    }

    // ---- the replay's thread ----

    /**
     * One run of the replay, from a start to its shutdown: the recording, its clock (guarded by
     * this player) and the thread that applies the polls.
     */
    private final class Player implements Run, Runnable {

        private final RobotLinkModel server;
        private final Recording recording;
        private final ReplayClock replayClock;
        private final Thread thread;
        private volatile boolean stopped;
        /** Set by a control: the thread looks again at once. */
        private boolean woken;
        /** The poll applied last and the registered robots it was applied to (after its kicks); the thread's own. */
        private int appliedIndex = -1;
        private List<String> appliedTo = List.of();
        private boolean saidEnd;
        /** A failure already logged (a listener that throws); null after a good poll. */
        private String failure;

        Player(RobotLinkModel server, Recording recording, ReplayClock replayClock) {
            this.server = server;
            this.recording = recording;
            this.replayClock = replayClock;
            thread = new Thread(this, "replay");
            thread.setDaemon(true);
            thread.start();
        }

        @Override
        public double durationSeconds() {
            return recording.durationMillis() / 1000.0;
        }

        @Override
        public synchronized double timeSeconds() {
            return replayClock.time(clock.getAsLong()) / 1000.0;
        }

        /** The poll applied last, as GETSS reads it (the model's {@code applied}, swapped whole by this thread). */
        @Override
        public double pollSeconds() {
            int index = applied.index();
            return index < 0 ? 0 : recording.pollMillis(index) / 1000.0;
        }

        @Override
        public synchronized double speed() {
            return replayClock.speed();
        }

        @Override
        public synchronized boolean playing() {
            return replayClock.playing(clock.getAsLong());
        }

        @Override
        public void play() {
            boolean changed;
            synchronized (this) {
                changed = !replayClock.playing(clock.getAsLong());
                replayClock.play(clock.getAsLong());
                wake();
            }
            moved(changed);
        }

        @Override
        public void pause() {
            boolean changed;
            synchronized (this) {
                changed = replayClock.playing(clock.getAsLong());
                replayClock.pause(clock.getAsLong());
                wake();
            }
            moved(changed);
        }

        @Override
        public void speed(double times) {
            boolean changed;
            synchronized (this) {
                changed = times != replayClock.speed();
                replayClock.speed(times, clock.getAsLong());
                wake();
            }
            moved(changed);
        }

        @Override
        public void jump(double seconds) {
            synchronized (this) {
                // The duration in seconds times 1000 may come back a hair above it in milliseconds.
                double millis = Math.min(seconds * 1000, recording.durationMillis());
                replayClock.jump(millis, clock.getAsLong());
                log.fine("replay: jumped to " + minutesSeconds((long) millis));
                wake();
            }
            moved(true);
        }

        /**
         * Tells the listeners where the replay is after a move that changed something (the event
         * log and the recording keep every one: the log's lines are limited), outside this
         * player's lock: the listeners take the server's.
         */
        private void moved(boolean changed) {
            if (changed) {
                listener().replayMoved(timeSeconds(), speed(), playing());
            }
        }

        @Override
        public synchronized List<Wall> walls() {
            return recording.wallsAt(replayClock.millis(clock.getAsLong()));
        }

        private void wake() {
            woken = true;
            notifyAll();
        }

        @Override
        public void stop() {
            synchronized (this) {
                stopped = true;
                notifyAll();
            }
            try {
                thread.join(TimeUnit.SECONDS.toMillis(5));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        @Override
        public void run() {
            while (!stopped) {
                long millis;
                boolean atEnd;
                synchronized (this) {
                    long now = clock.getAsLong();
                    millis = replayClock.millis(now);
                    atEnd = replayClock.atEnd(now);
                    woken = false;
                }
                // Before the first poll, the first: a replay that starts or jumps to 0 shows the run's beginning.
                int index = Math.max(0, recording.pollIndexAt(millis));
                try {
                    List<String> registered = server.getListOfRegisteredRobots();
                    if (index != appliedIndex || !registered.equals(appliedTo)) {
                        apply(index, registered);
                    }
                    failure = null;
                } catch (IOException | RuntimeException | Error e) {
                    failed(e);
                }
                if (atEnd && !saidEnd) {
                    log.info("the replay reached its end at " + minutesSeconds(recording.durationMillis()));
                }
                saidEnd = atEnd;
                pause(index);
            }
        }

        /** Waits until the next poll is due, a control wakes the thread, or a tick passes. */
        private synchronized void pause(int index) {
            if (woken || stopped) {
                return;
            }
            long waitNanos = TICK_NANOS;
            if (index + 1 < recording.polls().size()) {
                waitNanos = Math.min(waitNanos, replayClock.nanosUntil(recording.pollMillis(index + 1), clock.getAsLong()));
            }
            if (waitNanos <= 0) {
                return;
            }
            try {
                TimeUnit.NANOSECONDS.timedWait(this, waitNanos);
            } catch (InterruptedException e) {
                stopped = true;
            }
        }

        /**
         * Applies the poll as a simulator model applies its own ({@link #applyPoll}), with the
         * recorded state of every pair of present robots.
         */
        private void apply(int index, List<String> registeredBefore) throws IOException {
            Entry.Poll poll = recording.polls().get(index);
            Map<String, ReportedRobot> listed = new LinkedHashMap<>();
            Map<String, ModelPoll.Robot> robots = new HashMap<>();
            for (ModelPoll.Robot robot : poll.robots()) {
                Position at = robot.position();
                listed.put(robot.name(), new ReportedRobot(robot.name(), at.x(), at.y(), at.z(), robot.batteryEmpty()));
                robots.put(robot.name(), robot);
            }
            List<String> appliedNow = applyPoll(new Poll(registeredBefore, listed, true, "recording", " at " + minutesSeconds(poll.millis()),
                    recording.wallsAt(poll.millis()), () -> stopped), present -> {
                        // A pair this poll has no row for keeps the state it was last recorded in (its robots left
                        // the recorded run before its end); one never recorded (the two were never there together) is up.
                        List<RobotPair> pairs = PollStep.pairs(present);
                        Map<RobotPair, ModelPoll.Pair> rows = new HashMap<>();
                        poll.pairs().forEach(row -> rows.put(RobotPair.of(row.first(), row.second()), row));
                        Set<RobotPair> missing = new HashSet<>(pairs);
                        missing.removeAll(rows.keySet());
                        if (!missing.isEmpty() && index > 0) {
                            rows.putAll(recording.lastRows(index - 1, missing));
                        }
                        List<ModelPoll.Pair> decided = new ArrayList<>();
                        for (RobotPair pair : pairs) {
                            ModelPoll.Pair row = rows.get(pair);
                            decided.add(row != null ? new ModelPoll.Pair(pair.first(), pair.second(), row.strength(), row.obstacles(), row.live())
                                    : new ModelPoll.Pair(pair.first(), pair.second(), Double.NaN, Double.NaN, true));
                        }
                        if (stopped) {
                            return null;
                        }
                        // Only now, whole: a GETSS meanwhile answers from the poll before.
                        applied = new Applied(index, robots, rows);
                        return decided;
                    });
            if (appliedNow != null) {
                appliedIndex = index;
                appliedTo = appliedNow;
            }
        }

        /** A failure that is not the recording's (a bug, a listener that throws): logged once, then the replay goes on. */
        private void failed(Throwable e) {
            if (failure == null) {
                log.log(Level.WARNING, "the replay: applying a poll failed (" + e + "); the replay goes on", e);
            }
            failure = e.toString();
        }
    }
}
