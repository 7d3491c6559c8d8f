package org.usarsim.wss.model;

/**
 * A model that replays a recording (docs/replay.md) and lets the window's time bar and the
 * operator's {@code REPLAY} command move it: play, pause, speed, jump. Thread-safe; every method
 * returns at once (a jump's breaks and resumes are applied by the model's own thread).
 */
public interface Replay {

    /** The slowest and fastest speeds. */
    double MIN_SPEED = 0.25;
    double MAX_SPEED = 8;

    /** The recording's length in seconds: the time of its last poll or event. */
    double durationSeconds();

    /** Where the replay is, in seconds from the recording's start. */
    double timeSeconds();

    /**
     * The recorded time, in seconds, of the poll the replay applied last: what GETSS, DNS and the
     * map answer from. It follows {@link #timeSeconds()} as soon as the model's thread has applied
     * the poll due (a moment later on a busy machine); 0 before the first.
     */
    double pollSeconds();

    /** How fast the replay runs: 1 is as recorded. */
    double speed();

    boolean playing();

    void play();

    void pause();

    /** @throws IllegalArgumentException unless {@link #MIN_SPEED} to {@link #MAX_SPEED} */
    void speed(double times);

    /** Goes to that time; @throws IllegalArgumentException unless 0 to {@link #durationSeconds()} */
    void jump(double seconds);
}
