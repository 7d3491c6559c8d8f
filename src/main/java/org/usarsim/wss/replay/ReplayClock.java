package org.usarsim.wss.replay;

/**
 * Where a replay is in its recording: its time in milliseconds from the recording's start, as a
 * function of the time now (nanoseconds, as {@link System#nanoTime()}), the speed, play or pause,
 * the jumps and the end. It starts playing at the start offset; at the end it stops, paused, unless
 * it loops: then it wraps to 0 and goes on. A change of speed, a pause or a play takes the time
 * where it is, so the time never jumps but by {@link #jump}.
 *
 * <p>Pure: no thread, no clock of its own, every time passed in; not thread-safe (the replay's
 * model guards it).
 */
final class ReplayClock {

    private final long durationMillis;
    private final boolean loop;
    private double speed;
    private boolean playing = true;
    /** The replay's time at {@link #baseNanos}: every change starts from here. */
    private double baseMillis;
    private long baseNanos;

    /**
     * A replay of a recording {@code durationMillis} long that plays from {@code startMillis}
     * (at most the duration) at {@code speed} from {@code now}.
     */
    ReplayClock(long durationMillis, boolean loop, long startMillis, double speed, long now) {
        if (durationMillis < 0 || startMillis < 0 || startMillis > durationMillis || !(speed > 0)) {
            throw new IllegalArgumentException("a replay of " + durationMillis + " ms from " + startMillis + " ms at " + speed);
        }
        this.durationMillis = durationMillis;
        this.loop = loop;
        this.speed = speed;
        baseMillis = startMillis;
        baseNanos = now;
        stopAtEnd();
    }

    /** The replay's time at {@code now}, in milliseconds from the recording's start (fractions kept). */
    double time(long now) {
        if (!playing) {
            return baseMillis;
        }
        double time = baseMillis + (now - baseNanos) / 1e6 * speed;
        // A jump to the end reads as the end until the time moves on (REPLAY {Time <duration>} answers
        // the duration, looping or not); then a loop wraps.
        if (time < durationMillis || now == baseNanos) {
            return Math.min(time, durationMillis);
        }
        if (!loop || durationMillis == 0) {
            return durationMillis;
        }
        return time % durationMillis;
    }

    /** The replay's time at {@code now}, in whole milliseconds. */
    long millis(long now) {
        return (long) Math.floor(time(now));
    }

    /** Whether the time moves at {@code now}: played, and not stopped at the end. */
    boolean playing(long now) {
        return playing && !atEnd(now);
    }

    /** Whether the replay, not looping, has reached its end at {@code now}. */
    boolean atEnd(long now) {
        return !loop && time(now) >= durationMillis;
    }

    double speed() {
        return speed;
    }

    long durationMillis() {
        return durationMillis;
    }

    /** Holds the time where it is at {@code now}. */
    void pause(long now) {
        rebase(now);
        playing = false;
    }

    /** Lets the time move from where it is at {@code now}; from the start again when it stopped at the end. */
    void play(long now) {
        rebase(now);
        if (!loop && baseMillis >= durationMillis) {
            baseMillis = 0;
        }
        playing = true;
    }

    /** From {@code now} on, the time moves {@code times} as fast as recorded (above 0). */
    void speed(double times, long now) {
        if (!(times > 0) || Double.isInfinite(times)) {
            throw new IllegalArgumentException("a speed of " + times);
        }
        rebase(now);
        speed = times;
    }

    /** Puts the time at {@code millis} (0 to the duration) at {@code now}, playing or paused as it was. */
    void jump(double millis, long now) {
        if (!(millis >= 0 && millis <= durationMillis)) {
            throw new IllegalArgumentException(millis + " ms is not in the recording (0 to " + durationMillis + " ms)");
        }
        rebase(now);
        baseMillis = millis;
        stopAtEnd();
    }

    /**
     * The nanoseconds from {@code now} until the replay's time reaches {@code millis}, at this speed:
     * 0 when it has; {@link Long#MAX_VALUE} while it does not move.
     */
    long nanosUntil(long millis, long now) {
        double time = time(now);
        if (millis <= time) {
            return 0;
        }
        if (!playing(now)) {
            return Long.MAX_VALUE;
        }
        return (long) Math.ceil((millis - time) / speed * 1e6);
    }

    /** Takes the time where it is at {@code now} as the base of what follows. */
    private void rebase(long now) {
        baseMillis = time(now);
        baseNanos = now;
        stopAtEnd();
    }

    /** A replay that does not loop stops, paused, at its end. */
    private void stopAtEnd() {
        if (!loop && baseMillis >= durationMillis) {
            baseMillis = durationMillis;
            playing = false;
        }
    }
}
