package org.usarsim.wss.replay;

import java.util.function.Supplier;
import org.usarsim.wss.model.Replay;

/**
 * The replay's controls, for the window's time bar and the operator's {@code REPLAY} command: they
 * check what they are asked, then act on the run of the moment (nothing while stopped).
 */
final class ReplayControls implements Replay {

    private final Supplier<ReplayRun> run;

    /** Controls of whatever run {@code run} gives at each call. */
    ReplayControls(Supplier<ReplayRun> run) {
        this.run = run;
    }

    @Override
    public double durationSeconds() {
        return run.get().durationSeconds();
    }

    @Override
    public double timeSeconds() {
        return run.get().timeSeconds();
    }

    @Override
    public double pollSeconds() {
        return run.get().pollSeconds();
    }

    @Override
    public double speed() {
        return run.get().speed();
    }

    @Override
    public boolean playing() {
        return run.get().playing();
    }

    @Override
    public void play() {
        run.get().play();
    }

    @Override
    public void pause() {
        run.get().pause();
    }

    @Override
    public void speed(double times) {
        if (!(times >= MIN_SPEED && times <= MAX_SPEED)) {
            throw new IllegalArgumentException("a speed of " + times + " is not from " + MIN_SPEED + " to " + MAX_SPEED);
        }
        run.get().speed(times);
    }

    @Override
    public void jump(double seconds) {
        ReplayRun running = run.get();
        double duration = running.durationSeconds();
        if (!(seconds >= 0 && seconds <= duration)) {
            throw new IllegalArgumentException(seconds + " s is not in the recording (0 to " + duration + " s)");
        }
        running.jump(seconds);
    }
}
