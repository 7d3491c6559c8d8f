package org.usarsim.wss.replay;

import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.LongSupplier;
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
import org.usarsim.wss.model.simulator.PollingModel;
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
 * <p>Each run is a {@link ReplayPlayer} (its thread, {@code replay}, applies the polls), or
 * {@link ReplayRun#STOPPED}; {@link #replay()} gives the {@link ReplayControls}.
 */
public final class ReplayPropagationModel extends PollingModel {

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
    private final ReplayControls controls = new ReplayControls(() -> this.run);

    /** The replay of the current run, from a start to its shutdown; {@link ReplayRun#STOPPED} while stopped. */
    private volatile ReplayRun run = ReplayRun.STOPPED;
    /** The poll applied last, swapped whole by the player: GETSS, DNS, accepts and the map read it. */
    private volatile AppliedPoll applied = AppliedPoll.NONE;
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
            recording = RecordingReader.readPolled(Path.of(file));
        } catch (RecordingException e) {
            throw new ModelInputException(e.getMessage(), e);
        } catch (InvalidPathException e) {
            throw new ModelInputException("replay.file = '" + file + "' is not a path: " + e.getMessage(), e);
        }
        long startMillis = Math.round(values.getDouble("replay.start", 0) * 1000);
        if (startMillis > recording.durationMillis()) {
            throw new ModelInputException("replay.start = " + values.getString("replay.start", "") + " s is past the end of "
                    + file + " (" + minutesSeconds(recording.durationMillis()) + ")");
        }
        double speed = values.getDouble("replay.speed", 1);
        boolean loop = values.getBoolean("replay.loop", false);
        cutoff = cutoffOf(recording);
        applied = AppliedPoll.NONE;
        tell(file, recording, startMillis, speed, loop);
        run = new ReplayPlayer(new Host(), server, recording,
                new ReplayClock(recording.durationMillis(), loop, startMillis, speed, clock.getAsLong()), clock);
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
        ReplayRun stopping;
        synchronized (this) {
            stopping = run;
            run = ReplayRun.STOPPED;
        }
        stopping.stop();
    }

    @Override
    public boolean isActive() {
        return run != ReplayRun.STOPPED;
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

    /** The player's way back into the model: apply a poll, publish it, tell a move. */
    private final class Host implements ReplayPlayer.Host {

        @Override
        public List<String> apply(Poll poll, Decider decider) throws IOException {
            return applyPoll(poll, decider);
        }

        @Override
        public AppliedPoll applied() {
            return applied;
        }

        @Override
        public void applied(AppliedPoll poll) {
            applied = poll;
        }

        @Override
        public void moved(double timeSeconds, double speed, boolean playing) {
            listener().replayMoved(timeSeconds, speed, playing);
        }
    }
}
