package org.usarsim.wss.hub.core;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * A pair's condition one way as the threads that forward its bytes follow it (docs/shaping.md,
 * "How a link drives it"): the core sets it under its lock ({@link PairConditions}), a link's or
 * a fixed port's thread reads it at every step, and every thread that watches it is woken when
 * it changes, so a new rate or delay reaches a link at once, not at the end of the wait it was
 * in (a link at 1 bit/s waits a few milliseconds, one that holds only delayed bytes up to its
 * delay). The one place of that rule.
 *
 * <p>A wake-up is never lost: the new value is readable before the watchers run, and a watcher
 * is a {@link java.nio.channels.Selector#wakeup}, which makes the thread's next select return at
 * once if it is not in one. A thread watches before it reads the value for the first time.
 */
public final class LiveCondition {

    private volatile PairCondition value;
    /** Each wakes one thread; run under the hub's lock, so none may block. */
    private final List<Runnable> watchers = new CopyOnWriteArrayList<>();

    LiveCondition(PairCondition initial) {
        this.value = initial;
    }

    /** The condition now. */
    public PairCondition get() {
        return value;
    }

    /** The condition from now on; if it is another, every watcher is woken, after it can be read. @return the one before */
    PairCondition set(PairCondition now) {
        PairCondition before = value;
        value = now;
        if (!now.equals(before)) {
            watchers.forEach(Runnable::run);
        }
        return before;
    }

    /** Runs {@code wake} at every change from now on, until {@link #unwatch}; it must not block (a selector's wake-up). */
    public void watch(Runnable wake) {
        watchers.add(wake);
    }

    /** Stops running {@code wake}, the very one given to {@link #watch}. */
    public void unwatch(Runnable wake) {
        watchers.remove(wake);
    }
}
