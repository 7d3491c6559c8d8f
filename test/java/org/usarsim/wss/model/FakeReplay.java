package org.usarsim.wss.model;

import java.util.ArrayList;
import java.util.List;

/**
 * A {@link Replay} for tests: it keeps the state the calls set (the time moves only by
 * {@link #jump} and {@link #time(double)}) and records every call, as {@code play}, {@code pause},
 * {@code speed 4.0}, {@code jump 30.0}; it refuses what the interface says a replay refuses.
 */
public final class FakeReplay implements Replay {

    private final double duration;
    private final List<String> calls = new ArrayList<>();
    private double time;
    private double speed = 1;
    private boolean playing = true;
    private volatile java.util.function.DoubleConsumer onJump = seconds -> { };
    /** Applies the jumps in order, off the caller's thread. */
    private final java.util.concurrent.Executor applier = java.util.concurrent.Executors.newSingleThreadExecutor(task -> {
        Thread thread = new Thread(task, "fake-replay-jump");
        thread.setDaemon(true);
        return thread;
    });

    public FakeReplay(double durationSeconds) {
        this.duration = durationSeconds;
    }

    /** The calls so far, in order. */
    public synchronized List<String> calls() {
        return List.copyOf(calls);
    }

    /**
     * What a jump does besides moving the time (a replay model breaks and resumes pairs as
     * recorded at the new time): run on a thread of the fake's own, in order,, as a replay
     * model applies a jump on its own thread.
     */
    public void onJump(java.util.function.DoubleConsumer action) {
        onJump = action;
    }

    /** Moves the replay's time as playing would. */
    public synchronized void time(double seconds) {
        time = seconds;
    }

    @Override
    public double durationSeconds() {
        return duration;
    }

    @Override
    public synchronized double timeSeconds() {
        return time;
    }

    /** The fake applies no polls: the poll applied last stays the recording's start. */
    @Override
    public double pollSeconds() {
        return 0;
    }

    @Override
    public synchronized double speed() {
        return speed;
    }

    @Override
    public synchronized boolean playing() {
        return playing;
    }

    @Override
    public synchronized void play() {
        calls.add("play");
        playing = true;
    }

    @Override
    public synchronized void pause() {
        calls.add("pause");
        playing = false;
    }

    @Override
    public synchronized void speed(double times) {
        if (!(times >= MIN_SPEED && times <= MAX_SPEED)) {
            throw new IllegalArgumentException("speed " + times);
        }
        calls.add("speed " + times);
        speed = times;
    }

    @Override
    public synchronized void jump(double seconds) {
        if (!(seconds >= 0 && seconds <= duration)) {
            throw new IllegalArgumentException("time " + seconds);
        }
        calls.add("jump " + seconds);
        time = seconds;
        java.util.function.DoubleConsumer action = onJump;
        applier.execute(() -> action.accept(seconds));
    }
}
