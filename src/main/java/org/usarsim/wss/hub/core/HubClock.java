package org.usarsim.wss.hub.core;

/**
 * The hub's one clock (issue 32): every part of {@code hub/**} that needs the time reads it here,
 * never {@link System#nanoTime()} or {@link System#currentTimeMillis()} itself, so a hub-level
 * test can give a clock it moves. {@link #SYSTEM} in use.
 */
public interface HubClock {

    /** Monotonic nanoseconds, as {@link System#nanoTime()}: only differences mean anything. */
    long nanoTime();

    /** The wall clock in milliseconds since the epoch, as {@link System#currentTimeMillis()}: for what a log line says. */
    long wallMillis();

    /**
     * How long a thread that waits for this clock to move {@code clockNs} on sleeps (by the
     * machine's time) before it reads the clock again: that long on the machine's clock; a clock a
     * test moves by hand says less, so that a waiter sees the move at once. Every timed wait of the
     * hub goes through it: a timer's, a departure's drain, a registration waiting for a name.
     */
    default long waitNanos(long clockNs) {
        return clockNs;
    }

    /** The machine's clock. */
    HubClock SYSTEM = new HubClock() {
        @Override
        public long nanoTime() {
            return System.nanoTime();
        }

        @Override
        public long wallMillis() {
            return System.currentTimeMillis();
        }
    };
}
