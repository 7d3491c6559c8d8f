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
    long currentTimeMillis();

    /** The machine's clock. */
    HubClock SYSTEM = new HubClock() {
        @Override
        public long nanoTime() {
            return System.nanoTime();
        }

        @Override
        public long currentTimeMillis() {
            return System.currentTimeMillis();
        }
    };
}
