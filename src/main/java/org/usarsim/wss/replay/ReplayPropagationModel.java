package org.usarsim.wss.replay;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.model.ModelInputException;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.model.simulator.PollStep;
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
public final class ReplayPropagationModel implements PropagationModel {

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

    private final Logger log = Logger.getLogger(ReplayPropagationModel.class.getName());
    private final LongSupplier clock;
    private final Controls controls = new Controls();

    /** The values given by {@link #configure}, over the declared defaults: checked at each start. */
    private volatile Map<String, String> given = Map.of();
    private volatile RobotLinkModel linkModel;
    private volatile WssEventListener listener = new WssEventListener() {
    };
    /** The replay of the current run, from a start to its shutdown; null while stopped. */
    private volatile Player player;
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

    @Override
    public void configure(ModelSettings settings) {
        Map<String, String> values = new HashMap<>(given);
        values.putAll(settings.asMap());
        given = Map.copyOf(values);
    }

    @Override
    public void setRobotLinkModel(RobotLinkModel linkModel) {
        this.linkModel = linkModel;
    }

    @Override
    public void setEventListener(WssEventListener listener) {
        this.listener = listener;
    }

    /**
     * Reads the recording and starts replaying it.
     *
     * @throws ModelInputException when replay.file is empty, missing, not a recording, of another
     *                             version or without a poll, or replay.start is past its end
     */
    @Override
    public synchronized void start() throws ModelStartException {
        if (player != null) {
            return;
        }
        if (linkModel == null) {
            throw new ModelStartException("no server to act on (setRobotLinkModel was not called)");
        }
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
        player = new Player(recording, new ReplayClock(recording.durationMillis(), loop, startMillis, speed, clock.getAsLong()));
    }

    /** The given values over the declared defaults, each by its rule. */
    private ModelSettings checked() throws ModelInputException {
        Map<String, String> stripped = new LinkedHashMap<>();
        given.forEach((key, value) -> stripped.put(key, value.strip()));
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
                + minutesSeconds(startMillis) + " at " + java.math.BigDecimal.valueOf(speed).stripTrailingZeros().toPlainString() + "x" + (loop ? ", looping" : ""));
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
        Player stopping;
        synchronized (this) {
            stopping = player;
            player = null;
        }
        if (stopping != null) {
            stopping.stop();
        }
    }

    @Override
    public boolean isActive() {
        return player != null;
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
        Player running = player;
        return running == null ? List.of() : running.recording.wallsAt(running.millis());
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

    /** The controls, for the window's time bar and the operator's REPLAY command: they act on the running replay. */
    private final class Controls implements Replay {

        @Override
        public double durationSeconds() {
            Player running = player;
            return running == null ? 0 : running.recording.durationMillis() / 1000.0;
        }

        @Override
        public double timeSeconds() {
            Player running = player;
            return running == null ? 0 : running.time() / 1000.0;
        }

        @Override
        public double pollSeconds() {
            Player running = player;
            int index = applied.index();
            return running == null || index < 0 ? 0 : running.recording.pollMillis(index) / 1000.0;
        }

        @Override
        public double speed() {
            Player running = player;
            return running == null ? 1 : running.speed();
        }

        @Override
        public boolean playing() {
            Player running = player;
            return running != null && running.playing();
        }

        @Override
        public void play() {
            Player running = player;
            if (running != null) {
                running.play();
            }
        }

        @Override
        public void pause() {
            Player running = player;
            if (running != null) {
                running.pause();
            }
        }

        @Override
        public void speed(double times) {
            if (!(times >= MIN_SPEED && times <= MAX_SPEED)) {
                throw new IllegalArgumentException("a speed of " + times + " is not from " + MIN_SPEED + " to " + MAX_SPEED);
            }
            Player running = player;
            if (running != null) {
                running.speed(times);
            }
        }

        @Override
        public void jump(double seconds) {
            double duration = durationSeconds();
            if (!(seconds >= 0 && seconds <= duration)) {
                throw new IllegalArgumentException(seconds + " s is not in the recording (0 to " + duration + " s)");
            }
            Player running = player;
            if (running != null) {
                // The duration in seconds times 1000 may come back a hair above it in milliseconds.
                running.jump(Math.min(seconds * 1000, running.recording.durationMillis()));
            }
        }
    }

    // ---- the replay's thread ----

    /**
     * One run of the replay, from a start to its shutdown: the recording, its clock (guarded by
     * this player) and the thread that applies the polls.
     */
    private final class Player implements Runnable {

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

        Player(Recording recording, ReplayClock replayClock) {
            this.recording = recording;
            this.replayClock = replayClock;
            thread = new Thread(this, "replay");
            thread.setDaemon(true);
            thread.start();
        }

        synchronized long millis() {
            return replayClock.millis(clock.getAsLong());
        }

        synchronized double time() {
            return replayClock.time(clock.getAsLong());
        }

        synchronized double speed() {
            return replayClock.speed();
        }

        synchronized boolean playing() {
            return replayClock.playing(clock.getAsLong());
        }

        synchronized void play() {
            replayClock.play(clock.getAsLong());
            wake();
        }

        synchronized void pause() {
            replayClock.pause(clock.getAsLong());
            wake();
        }

        synchronized void speed(double times) {
            replayClock.speed(times, clock.getAsLong());
            wake();
        }

        synchronized void jump(double millis) {
            replayClock.jump(millis, clock.getAsLong());
            log.fine("replay: jumped to " + minutesSeconds((long) millis));
            wake();
        }

        private void wake() {
            woken = true;
            notifyAll();
        }

        void stop() {
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
                    List<String> registered = linkModel.getListOfRegisteredRobots();
                    if (index != appliedIndex || !registered.equals(appliedTo)) {
                        apply(index, registered);
                    }
                    failure = null;
                } catch (RuntimeException | Error e) {
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
         * Applies the poll as a simulator model applies its own: kicks, then the state of every
         * pair of present robots published, announced ({@code polled}) and set in one go.
         */
        private void apply(int index, List<String> registeredBefore) {
            Entry.Poll poll = recording.polls().get(index);
            Map<String, ReportedRobot> listed = new LinkedHashMap<>();
            Map<String, ModelPoll.Robot> robots = new HashMap<>();
            for (ModelPoll.Robot robot : poll.robots()) {
                Position at = robot.position();
                listed.put(robot.name(), new ReportedRobot(robot.name(), at.x(), at.y(), at.z(), robot.batteryEmpty()));
                robots.put(robot.name(), robot);
            }
            List<ModelPoll.Kick> kicks = new ArrayList<>();
            for (PollStep.Kick kick : PollStep.kicks(registeredBefore, listed, true)) {
                if (stopped) {
                    return;
                }
                log.info("kicking " + kick.robot() + ": " + kick.reason("recording") + " at " + minutesSeconds(poll.millis()));
                if (kick.batteryEmpty()) {
                    listener.robotOutOfBattery(kick.robot());
                }
                linkModel.kickOutRobot(kick.robot());
                kicks.add(new ModelPoll.Kick(kick.robot(), kick.batteryEmpty()));
            }
            List<String> registered = linkModel.getListOfRegisteredRobots();
            Map<RobotPair, ModelPoll.Pair> recorded = new HashMap<>();
            poll.pairs().forEach(pair -> recorded.put(RobotPair.of(pair.first(), pair.second()), pair));
            // A pair the poll has no row for (one of the two had not registered when it was recorded) stays up.
            List<ModelPoll.Pair> decided = new ArrayList<>();
            for (RobotPair pair : PollStep.pairs(PollStep.present(registered, listed))) {
                ModelPoll.Pair row = recorded.get(pair);
                decided.add(row != null ? new ModelPoll.Pair(pair.first(), pair.second(), row.strength(), row.obstacles(), row.live())
                        : new ModelPoll.Pair(pair.first(), pair.second(), Double.NaN, Double.NaN, true));
            }
            if (stopped) {
                return;
            }
            // Only now, whole: a GETSS meanwhile answers from the poll before.
            applied = new Applied(index, robots, recorded);
            listener.polled(new ModelPoll(poll.robots(), kicks, decided, recording.wallsAt(poll.millis())));
            Map<RobotPair, Boolean> inRange = new LinkedHashMap<>();
            decided.forEach(pair -> inRange.put(RobotPair.of(pair.first(), pair.second()), pair.live()));
            Set<RobotPair> changed = linkModel.applyLinkStates(inRange);
            for (ModelPoll.Pair pair : decided) {
                if (!changed.contains(RobotPair.of(pair.first(), pair.second()))) {
                    continue;
                }
                if (pair.live()) {
                    listener.connectionInRange(pair.first(), pair.second());
                } else {
                    double distance = robots.get(pair.first()).position().distanceTo(robots.get(pair.second()).position());
                    listener.connectionOutOfRange(pair.first(), pair.second(), pair.strength(), distance);
                }
            }
            appliedIndex = index;
            appliedTo = registered;
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
