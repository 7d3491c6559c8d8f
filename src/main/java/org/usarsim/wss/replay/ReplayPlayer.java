package org.usarsim.wss.replay;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.ThreadStop;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.model.simulator.PollStep;
import org.usarsim.wss.model.simulator.PollingModel;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.Recording;

/**
 * One run of the replay, from a start to its shutdown: the recording, its clock (guarded by this
 * player) and the thread, {@code replay}, that applies the polls. It applies a poll when the
 * replay's time reaches it (a jump, a change of speed or play wakes it at once) and when the
 * registered robots change, so that a robot that registers while the replay holds still is decided
 * too; it waits until the next poll is due, {@link #TICK_NANOS} at most.
 */
final class ReplayPlayer implements ReplayRun, Runnable {

    /** How long the replay's thread waits at most before it looks again. */
    private static final long TICK_NANOS = TimeUnit.MILLISECONDS.toNanos(20);

    /** The model's log: the player's lines are the replay's. */
    private static final Logger LOG = Logger.getLogger(ReplayPropagationModel.class.getName());

    /** What the player asks of its model. */
    interface Host {

        /** Applies the poll as the simulator models apply theirs ({@code PollingModel.applyPoll}). */
        List<String> apply(PollingModel.Poll poll, PollingModel.Decider decider) throws IOException;

        /** The poll applied last. */
        AppliedPoll applied();

        /** Publishes the poll just decided, whole: GETSS answers from it from now on. */
        void applied(AppliedPoll poll);

        /** Tells the listeners where the replay is after a move that changed something. */
        void moved(double timeSeconds, double speed, boolean playing);
    }

    private final Host host;
    private final RobotLinkModel server;
    private final Recording recording;
    private final ReplayClock replayClock;
    private final LongSupplier clock;
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

    /** Starts the thread that replays {@code recording} on {@code replayClock}, its time read from {@code clock}. */
    ReplayPlayer(Host host, RobotLinkModel server, Recording recording, ReplayClock replayClock, LongSupplier clock) {
        this.host = host;
        this.server = server;
        this.recording = recording;
        this.replayClock = replayClock;
        this.clock = clock;
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

    /** The poll applied last, as GETSS reads it (the model's, swapped whole by this thread). */
    @Override
    public double pollSeconds() {
        int index = host.applied().index();
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
            LOG.fine("replay: jumped to " + ReplayPropagationModel.minutesSeconds((long) millis));
            wake();
        }
        moved(true);
    }

    /**
     * Tells the listeners where the replay is after a move that changed something (the event log
     * and the recording keep every one: the log's lines are limited), outside this player's lock:
     * the listeners take the server's.
     */
    private void moved(boolean changed) {
        if (changed) {
            host.moved(timeSeconds(), speed(), playing());
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
        ThreadStop.stop(thread, () -> {
            synchronized (this) {
                stopped = true;
                notifyAll();
            }
        });
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
                LOG.info("the replay reached its end at " + ReplayPropagationModel.minutesSeconds(recording.durationMillis()));
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
     * Applies the poll as a simulator model applies its own ({@link Host#apply}), with the
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
        List<String> appliedNow = host.apply(new PollingModel.Poll(registeredBefore, listed, true, "recording",
                " at " + ReplayPropagationModel.minutesSeconds(poll.millis()), recording.wallsAt(poll.millis()), () -> stopped),
                present -> {
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
                    host.applied(new AppliedPoll(index, robots, rows));
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
            LOG.log(Level.WARNING, "the replay: applying a poll failed (" + e + "); the replay goes on", e);
        }
        failure = e.toString();
    }
}
